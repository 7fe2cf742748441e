//! The rules every export follows: a status for every outcome, the last
//! error's sentence kept per thread, no panic across the boundary, NULL
//! checked rather than asserted, outputs written only on success.
//!
//! The exports stay `unsafe extern "C" fn`: each reads or writes memory the
//! caller points to, which only the caller can vouch for, so a safe
//! signature would let safe Rust reach undefined behaviour. Instead every
//! unsafe operation sits in an explicit `unsafe` block whose `SAFETY:` note
//! names the promise it relies on, and the helpers below are the only code
//! that turns a pointer into a reference or a slice.

use std::cell::RefCell;
use std::ffi::{c_char, CString};
use std::panic::{catch_unwind, AssertUnwindSafe};

use glam::DVec3;

use crate::error::{Error, MeshError, MAX_ELEMENTS};
use crate::ffi::mesh::WeftMesh;
use crate::mesh::Mesh;

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
            Error::BufferTooSmall(_) => WeftStatus::BufferTooSmall,
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
    // SAFETY: `pointer` is NULL (`as_ref` gives None) or points to a live `T`,
    // as the caller promises.
    unsafe { pointer.as_ref() }
        .ok_or_else(|| Failure::new(WeftStatus::NullPointer, format!("{name} is NULL")))
}

/// Writes `value` through an out-parameter that may be NULL (an optional
/// output the caller did not ask for).
///
/// # Safety
/// `pointer` is NULL or points to a writable `T`.
pub(crate) unsafe fn write_optional<T>(pointer: *mut T, value: T) {
    // SAFETY: `pointer` is NULL (`as_mut` gives None) or writable, as the
    // caller promises.
    if let Some(slot) = unsafe { pointer.as_mut() } {
        *slot = value;
    }
}

/// Runs an export that makes a mesh: checks `out_mesh` first and writes the
/// result only on success.
///
/// # Safety
/// `out_mesh` is NULL or writable.
pub(crate) unsafe fn make_mesh(
    out_mesh: *mut *mut WeftMesh,
    op: impl FnOnce() -> Result<Mesh, Failure>,
) -> WeftStatus {
    guard(|| {
        let out = out_param(out_mesh, "out_mesh")?;
        let result = op()?;
        // SAFETY: `out` is the caller's writable `out_mesh`, checked not NULL.
        unsafe { WeftMesh::write(out, result) };
        Ok(())
    })
}

/// Runs a mesh-to-mesh export: checks `out_mesh` first, borrows the input,
/// and writes the result only on success.
///
/// # Safety
/// `mesh` is NULL or a live handle; `out_mesh` is NULL or writable.
pub(crate) unsafe fn mesh_op(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    op: impl FnOnce(&Mesh) -> Result<Mesh, Failure>,
) -> WeftStatus {
    let borrow_and_run = || {
        // SAFETY: `mesh` is NULL or a live handle, as the caller promises.
        let mesh = unsafe { crate::ffi::mesh::mesh_ref(mesh, "mesh") }?;
        op(mesh)
    };
    // SAFETY: `out_mesh` is NULL or writable, as the caller promises.
    unsafe { make_mesh(out_mesh, borrow_and_run) }
}

/// As `mesh_op`, for an export whose arguments the library checks itself:
/// the library's error becomes the status unchanged.
///
/// # Safety
/// As `mesh_op`.
pub(crate) unsafe fn forward_mesh_op<E>(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    op: impl FnOnce(&Mesh) -> Result<Mesh, E>,
) -> WeftStatus
where
    Failure: From<E>,
{
    // SAFETY: `mesh` and `out_mesh` are as `mesh_op` requires, as the caller promises.
    unsafe { mesh_op(mesh, out_mesh, |m| Ok(op(m)?)) }
}

/// As `mesh_op`, for an operation that also counts what it changed: the
/// count goes to `out_count` unless that is NULL, on success only.
///
/// # Safety
/// As `mesh_op`; `out_count` is NULL or writable.
pub(crate) unsafe fn counted_mesh_op(
    mesh: *const WeftMesh,
    out_mesh: *mut *mut WeftMesh,
    out_count: *mut usize,
    op: impl FnOnce(&Mesh) -> Result<(Mesh, usize), Failure>,
) -> WeftStatus {
    let run_and_count = |mesh: &Mesh| {
        let (result, count) = op(mesh)?;
        // SAFETY: `out_count` is NULL or writable, as the caller promises.
        unsafe { write_optional(out_count, count) };
        Ok(result)
    };
    // SAFETY: `mesh` and `out_mesh` are as `mesh_op` requires, as the caller promises.
    unsafe { mesh_op(mesh, out_mesh, run_and_count) }
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
fn check_buffer<T>(pointer: *const T, len: usize, name: &str) -> Result<(), Failure> {
    if pointer.is_null() {
        return Err(Failure::new(
            WeftStatus::NullPointer,
            format!("{name} is NULL but its length is {len}"),
        ));
    }
    if !pointer.is_aligned() {
        return Err(Failure::invalid_argument(format!(
            "{name} at {pointer:p} is not aligned to {} bytes, as its element type requires",
            std::mem::align_of::<T>()
        )));
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
    check_buffer(pointer, len, name)?;
    // SAFETY: `pointer` is not NULL, holds `len` readable elements for `'a`
    // (the caller's promise) and `len` elements fit in `isize::MAX` bytes.
    Ok(unsafe { std::slice::from_raw_parts(pointer, len) })
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
    check_buffer(pointer.cast_const(), len, name)?;
    // SAFETY: `pointer` is not NULL, holds `len` writable elements for `'a`
    // (the caller's promise) and `len` elements fit in `isize::MAX` bytes.
    Ok(unsafe { std::slice::from_raw_parts_mut(pointer, len) })
}

/// Copies `values` into the caller buffer `pointer` of `capacity`
/// elements, once it is known to have room (else nothing is written).
///
/// # Safety
/// As [`output_slice`] with `len` = `capacity`.
pub(crate) unsafe fn copy_out<T: Copy>(
    pointer: *mut T,
    capacity: usize,
    name: &str,
    values: &[T],
) -> Result<(), Failure> {
    check_room(name, capacity, values.len())?;
    // SAFETY: as this function's `# Safety` section requires.
    let out = unsafe { output_slice(pointer, capacity, name)? };
    out[..values.len()].copy_from_slice(values);
    Ok(())
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

/// Checks a count of points against the cap and returns the number of
/// doubles they take, before any buffer is viewed: a count past the cap
/// never becomes a slice.
pub(crate) fn point_count_arg(count: usize, name: &str) -> Result<usize, Failure> {
    if count as u64 > MAX_ELEMENTS {
        return Err(Failure::new(
            WeftStatus::InputTooLarge,
            format!("{name}: a count of {count} points exceeds the limit of {MAX_ELEMENTS}"),
        ));
    }
    count.checked_mul(3).ok_or_else(|| {
        Failure::new(
            WeftStatus::InputTooLarge,
            format!("{name}: a count of {count} points is larger than memory can hold"),
        )
    })
}

/// Reads `count` points of three doubles, naming the first non-finite one.
///
/// # Safety
/// `points` is NULL or holds `3 * count` doubles.
pub(crate) unsafe fn points_arg(
    points: *const f64,
    count: usize,
    name: &str,
) -> Result<Vec<DVec3>, Failure> {
    let length = point_count_arg(count, name)?;
    // SAFETY: `points` is NULL or holds `3 * count` doubles, as the caller promises.
    let flat = unsafe { input_slice(points, length, name) }?;
    let mut out = Vec::new();
    out.try_reserve_exact(count).map_err(|_| {
        Failure::new(
            WeftStatus::OutOfMemory,
            format!("could not copy the {count} points of {name}"),
        )
    })?;
    for (i, c) in flat.chunks_exact(3).enumerate() {
        let p = DVec3::new(c[0], c[1], c[2]);
        if !p.is_finite() {
            return Err(Failure::new(
                WeftStatus::NonFiniteCoordinate,
                format!(
                    "{name}: point {i} has a non-finite coordinate ({}, {}, {})",
                    p.x, p.y, p.z
                ),
            ));
        }
        out.push(p);
    }
    Ok(out)
}
