//! The rules every export follows: a status for every outcome, the last
//! error's sentence kept per thread, no panic across the boundary, NULL
//! checked rather than asserted, outputs written only on success.

use std::cell::RefCell;
use std::ffi::{c_char, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::error::{Error, MeshError};

/// The outcome of every Weft function. The values are stable: new ones are
/// only ever added at the end.
#[repr(u32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WeftStatus {
    /// Success.
    Ok = 0,
    /// A required pointer argument was NULL.
    NullPointer = 1,
    /// An argument other than a mesh is out of its domain (an unknown enum
    /// value, a negative tolerance, a level count above the cap).
    InvalidArgument = 2,
    /// A face names a vertex index at or past the vertex count.
    IndexOutOfRange = 3,
    /// A face has fewer than three vertices.
    FaceTooSmall = 4,
    /// A face names the same vertex twice.
    RepeatedIndex = 5,
    /// A coordinate is NaN or infinite.
    NonFiniteCoordinate = 6,
    /// The face sizes do not add up to the index count, or a buffer length
    /// disagrees with a count.
    CountMismatch = 7,
    /// The input has more vertices or indices than 32-bit indices address.
    InputTooLarge = 8,
    /// An operation that needs triangles was given another polygon.
    NotTriangles = 9,
    /// The result would pass the size cap or overflow 32-bit indices.
    ResultTooLarge = 10,
    /// Memory for the result could not be allocated.
    OutOfMemory = 11,
    /// A caller buffer is too small for what is to be copied into it.
    BufferTooSmall = 12,
    /// The input is geometrically degenerate for the operation (collinear
    /// points, fewer points than needed, a zero-length axis).
    DegenerateInput = 13,
    /// A bug inside Weft was caught at the boundary; the host keeps running.
    InternalPanic = 14,
}

/// A failed call: its status and the sentence that explains it.
#[derive(Debug)]
pub(crate) struct Failure {
    pub(crate) status: WeftStatus,
    pub(crate) message: String,
}

impl Failure {
    pub(crate) fn new(status: WeftStatus, message: impl Into<String>) -> Failure {
        Failure {
            status,
            message: message.into(),
        }
    }

    pub(crate) fn invalid_argument(message: impl Into<String>) -> Failure {
        Failure::new(WeftStatus::InvalidArgument, message)
    }
}

impl From<MeshError> for Failure {
    fn from(error: MeshError) -> Failure {
        let status = match error {
            MeshError::IndexOutOfRange { .. } => WeftStatus::IndexOutOfRange,
            MeshError::FaceTooSmall { .. } => WeftStatus::FaceTooSmall,
            MeshError::RepeatedIndex { .. } => WeftStatus::RepeatedIndex,
            MeshError::NonFiniteCoordinate { .. } => WeftStatus::NonFiniteCoordinate,
            MeshError::CountMismatch { .. } => WeftStatus::CountMismatch,
            MeshError::TooLarge { .. } => WeftStatus::InputTooLarge,
        };
        Failure::new(status, format!("invalid mesh: {error}"))
    }
}

impl From<Error> for Failure {
    fn from(error: Error) -> Failure {
        let status = match &error {
            Error::InvalidMesh(inner) => return inner.clone().into(),
            Error::InvalidArgument(_) => WeftStatus::InvalidArgument,
            Error::NotTriangles { .. } => WeftStatus::NotTriangles,
            Error::ResultTooLarge(_) => WeftStatus::ResultTooLarge,
            Error::OutOfMemory(_) => WeftStatus::OutOfMemory,
            Error::DegenerateInput(_) => WeftStatus::DegenerateInput,
        };
        Failure::new(status, error.to_string())
    }
}

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

fn set_last_error(message: &str) {
    // A NUL inside a message would cut it short in C; replace it.
    let text = CString::new(message.replace('\0', " ")).unwrap_or_default();
    LAST_ERROR.with(|slot| *slot.borrow_mut() = text);
}

/// Pointer to the calling thread's last error message; valid until the next
/// failing call on this thread.
pub(crate) fn last_error_ptr() -> *const c_char {
    LAST_ERROR.with(|slot| slot.borrow().as_ptr())
}

/// Runs the body of an export: converts its error to a status, records the
/// sentence for this thread, and turns a panic into `InternalPanic`.
pub(crate) fn guard(body: impl FnOnce() -> Result<(), Failure>) -> WeftStatus {
    match catch_unwind(AssertUnwindSafe(body)) {
        Ok(Ok(())) => WeftStatus::Ok,
        Ok(Err(failure)) => {
            set_last_error(&failure.message);
            failure.status
        }
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            set_last_error(&format!(
                "internal error in Weft (please report it): {what}"
            ));
            WeftStatus::InternalPanic
        }
    }
}

/// The referent of a required input pointer.
///
/// # Safety
/// `pointer` is NULL or points to a live `T` for the lifetime `'a`.
pub(crate) unsafe fn required<'a, T>(pointer: *const T, name: &str) -> Result<&'a T, Failure> {
    pointer
        .as_ref()
        .ok_or_else(|| Failure::new(WeftStatus::NullPointer, format!("{name} is NULL")))
}

/// Checks an out-parameter before any work is done, so that a NULL output
/// fails fast and a success is the only time it is written.
pub(crate) fn out_param<T>(pointer: *mut T, name: &str) -> Result<*mut T, Failure> {
    if pointer.is_null() {
        Err(Failure::new(
            WeftStatus::NullPointer,
            format!("{name} is NULL"),
        ))
    } else {
        Ok(pointer)
    }
}

/// Checks a caller buffer's pointer and length before it is viewed as a slice.
fn check_buffer<T>(is_null: bool, len: usize, name: &str) -> Result<(), Failure> {
    if is_null {
        return Err(Failure::new(
            WeftStatus::NullPointer,
            format!("{name} is NULL but its length is {len}"),
        ));
    }
    if len
        .checked_mul(std::mem::size_of::<T>())
        .is_none_or(|bytes| bytes > isize::MAX as usize)
    {
        return Err(Failure::new(
            WeftStatus::InputTooLarge,
            format!("{name} has a length of {len}, larger than memory can hold"),
        ));
    }
    Ok(())
}

/// A borrowed input buffer of `len` elements; `(NULL, 0)` is the empty buffer.
///
/// # Safety
/// When not NULL, `pointer` points to `len` readable elements for `'a`.
pub(crate) unsafe fn input_slice<'a, T>(
    pointer: *const T,
    len: usize,
    name: &str,
) -> Result<&'a [T], Failure> {
    if len == 0 {
        return Ok(&[]);
    }
    check_buffer::<T>(pointer.is_null(), len, name)?;
    Ok(std::slice::from_raw_parts(pointer, len))
}

/// A caller output buffer of `len` elements; `(NULL, 0)` is the empty buffer.
///
/// # Safety
/// When not NULL, `pointer` points to `len` writable elements for `'a`.
pub(crate) unsafe fn output_slice<'a, T>(
    pointer: *mut T,
    len: usize,
    name: &str,
) -> Result<&'a mut [T], Failure> {
    if len == 0 {
        return Ok(&mut []);
    }
    check_buffer::<T>(pointer.is_null(), len, name)?;
    Ok(std::slice::from_raw_parts_mut(pointer, len))
}

/// Checks that a caller buffer of `len` elements has room for `needed`.
pub(crate) fn check_room(name: &str, len: usize, needed: usize) -> Result<(), Failure> {
    if len < needed {
        Err(Failure::new(
            WeftStatus::BufferTooSmall,
            format!("{name} has room for {len} elements but {needed} are needed"),
        ))
    } else {
        Ok(())
    }
}

/// Reads a C enumeration value, which arrives as a plain integer: an unknown
/// value is an error, never a Rust enum with an invalid discriminant.
pub(crate) fn enum_arg<T>(
    value: u32,
    name: &str,
    convert: impl FnOnce(u32) -> Option<T>,
    allowed: &str,
) -> Result<T, Failure> {
    convert(value).ok_or_else(|| {
        Failure::invalid_argument(format!("{name} is {value}; it must be {allowed}"))
    })
}
