//! Binary PLY bodies read in bulk. When every element's records have one
//! size but the faces' (whose index list sets theirs), each vertex is
//! decoded from its own offset on all threads, and the faces in two passes:
//! their lengths one after another, then their indices on all threads. A
//! file this reader does not take (another list, a body cut short, a
//! negative length or index, a non-finite colour read strictly) goes to the
//! general reader, which names what is wrong and where.

use std::sync::atomic::{AtomicBool, Ordering};

use glam::DVec3;
use rayon::prelude::*;

use super::{file_of, roles, Element, Property, Roles, Scalar};
use crate::io::mesh_file::{Colours, MeshFile};
use crate::io::{build_mesh_with, IoError, Location};
use crate::mesh::MeshOptions;

/// Vertices or faces per rayon task.
const CHUNK: usize = 4096;

/// The vertex element: where its records start, how many, their size, each
/// property's offset and type, and the properties' roles.
struct Vertices {
    start: usize,
    count: usize,
    record: usize,
    layout: Vec<(usize, Scalar)>,
    roles: Roles,
}

impl Vertices {
    /// Property `p` of vertex `v`.
    #[inline]
    fn value(&self, data: &[u8], big_endian: bool, v: usize, p: usize) -> f64 {
        let (offset, ty) = self.layout[p];
        let at = self.start + v * self.record + offset;
        ty.value_of(&data[at..at + ty.size()], big_endian)
    }
}

/// A face record: the scalar bytes before the index list, its length's
/// and items' types, the scalar bytes after.
struct FaceLayout {
    before: usize,
    count: Scalar,
    item: Scalar,
    after: usize,
}

/// The faces' records: where each starts and its corner count.
struct Faces {
    layout: FaceLayout,
    starts: Vec<usize>,
    sizes: Vec<u32>,
}

/// Reads a binary body that starts at byte `body` of `data`; `None` when
/// the general reader must (see the module doc).
pub(super) fn read_in_bulk(
    data: &[u8],
    body: usize,
    big_endian: bool,
    elements: &[Element],
    strict: bool,
    options: MeshOptions,
) -> Option<Result<MeshFile, IoError>> {
    let mut at = body;
    let mut vertices: Option<Vertices> = None;
    let mut faces: Option<Faces> = None;
    for element in elements {
        let roles = roles(element, strict).ok()?;
        if let (b"face", Some(list)) = (element.name.as_slice(), roles.index_list) {
            if faces.is_some() {
                return None;
            }
            let layout = face_layout(element, list)?;
            let (starts, sizes, end) = face_records(data, at, element.count, &layout, big_endian)?;
            faces = Some(Faces {
                layout,
                starts,
                sizes,
            });
            at = end;
            continue;
        }
        let (layout, record) = scalar_layout(element)?;
        let end = element.count.checked_mul(record)?.checked_add(at)?;
        if end > data.len() {
            return None;
        }
        if element.name == b"vertex" {
            if vertices.is_some() {
                return None;
            }
            vertices = Some(Vertices {
                start: at,
                count: element.count,
                record,
                layout,
                roles,
            });
        }
        at = end;
    }
    let (positions, colours, uvs) = match &vertices {
        Some(vertices) => decode_vertices(data, big_endian, vertices, strict)?,
        None => (Vec::new(), None, None),
    };
    let (sizes, indices, starts) = match faces {
        Some(faces) => {
            let indices = decode_indices(data, big_endian, &faces)?;
            (faces.sizes, indices, faces.starts)
        }
        None => (Vec::new(), Vec::new(), Vec::new()),
    };
    let (first, record) = vertices.as_ref().map_or((0, 0), |v| (v.start, v.record));
    let mesh = build_mesh_with(
        (positions, sizes, indices),
        options,
        |v| Location::Byte(first + v * record),
        |f| Location::Byte(starts[f]),
    );
    Some(mesh.map(|mesh| file_of(mesh, colours, uvs)))
}

/// Each property's offset and type in a record of only scalars, and the
/// record's size; `None` when a property is a list.
fn scalar_layout(element: &Element) -> Option<(Vec<(usize, Scalar)>, usize)> {
    let mut at = 0;
    let mut layout = Vec::with_capacity(element.properties.len());
    for (_, property) in &element.properties {
        let Property::Scalar(ty) = *property else {
            return None;
        };
        layout.push((at, ty));
        at += ty.size();
    }
    Some((layout, at))
}

/// The layout of a face record whose only list is property `list`.
fn face_layout(element: &Element, list: usize) -> Option<FaceLayout> {
    let (mut before, mut after, mut found) = (0, 0, None);
    for (p, (_, property)) in element.properties.iter().enumerate() {
        match *property {
            Property::Scalar(ty) if found.is_none() => before += ty.size(),
            Property::Scalar(ty) => after += ty.size(),
            Property::List { count, item } if p == list => found = Some((count, item)),
            Property::List { .. } => return None,
        }
    }
    let (count, item) = found?;
    Some(FaceLayout {
        before,
        count,
        item,
        after,
    })
}

/// Walks `count` face records from byte `at`: where each starts, its
/// corner count, and where the last ends; `None` when one does not fit in
/// `data` or has a negative count.
fn face_records(
    data: &[u8],
    mut at: usize,
    count: usize,
    layout: &FaceLayout,
    big_endian: bool,
) -> Option<(Vec<usize>, Vec<u32>, usize)> {
    let length = layout.count.size();
    let smallest = layout.before + length + layout.after;
    // A header that promises more faces than the file holds.
    if count > (data.len() - at) / smallest {
        return None;
    }
    let (mut starts, mut sizes) = (Vec::with_capacity(count), Vec::with_capacity(count));
    for _ in 0..count {
        let list = at + layout.before;
        let n = layout
            .count
            .value_of(data.get(list..list + length)?, big_endian);
        if !(0.0..=u32::MAX as f64).contains(&n) {
            return None;
        }
        let end = (n as usize)
            .checked_mul(layout.item.size())?
            .checked_add(list + length + layout.after)?;
        if end > data.len() {
            return None;
        }
        starts.push(at);
        sizes.push(n as u32);
        at = end;
    }
    Some((starts, sizes, at))
}

type DecodedVertices = (Vec<DVec3>, Option<Colours>, Option<Vec<[f64; 2]>>);

/// The vertices' positions, and their colours and texture coordinates when
/// the element has them; `None` for a non-finite colour read strictly.
fn decode_vertices(
    data: &[u8],
    big_endian: bool,
    vertices: &Vertices,
    strict: bool,
) -> Option<DecodedVertices> {
    let roles = &vertices.roles;
    let value = |v: usize, p: usize| vertices.value(data, big_endian, v, p);
    let all = || (0..vertices.count).into_par_iter().with_min_len(CHUNK);
    let [Some(x), Some(y), Some(z)] = roles.axes else {
        return None;
    };
    let mut positions = Vec::with_capacity(vertices.count);
    positions.par_extend(all().map(|v| DVec3::new(value(v, x), value(v, y), value(v, z))));
    let colours = match roles.colours {
        true => {
            let mut rgba = Vec::with_capacity(vertices.count);
            rgba.par_extend(all().map(|v| {
                let mut colour = [0.0, 0.0, 0.0, 1.0];
                for (channel, role) in colour.iter_mut().zip(roles.channels) {
                    if let Some((p, scale)) = role {
                        *channel = value(v, p) / scale;
                    }
                }
                colour
            }));
            if strict && rgba.par_iter().any(|c| c.iter().any(|c| !c.is_finite())) {
                return None;
            }
            Some(Colours {
                rgba,
                alpha: roles.alpha,
            })
        }
        false => None,
    };
    let uvs = match (roles.uvs, roles.uv_axes) {
        (true, [Some(s), Some(t)]) => {
            let mut uvs = Vec::with_capacity(vertices.count);
            uvs.par_extend(all().map(|v| [value(v, s), value(v, t)]));
            Some(uvs)
        }
        _ => None,
    };
    Some((positions, colours, uvs))
}

/// Every face's indices, in order; `None` when one is negative or past
/// `u32::MAX`.
fn decode_indices(data: &[u8], big_endian: bool, faces: &Faces) -> Option<Vec<u32>> {
    let FaceLayout {
        before,
        count,
        item,
        ..
    } = faces.layout;
    let (first, step) = (before + count.size(), item.size());
    let corners: usize = faces.sizes.iter().map(|&n| n as usize).sum();
    let out_of_range = AtomicBool::new(false);
    let mut indices = Vec::with_capacity(corners);
    indices.par_extend(
        (0..faces.sizes.len())
            .into_par_iter()
            .with_min_len(CHUNK)
            .flat_map_iter(|f| {
                let list = faces.starts[f] + first;
                let out_of_range = &out_of_range;
                (0..faces.sizes[f] as usize).map(move |k| {
                    let at = list + k * step;
                    let index = item.value_of(&data[at..at + step], big_endian);
                    if !(0.0..=u32::MAX as f64).contains(&index) {
                        out_of_range.store(true, Ordering::Relaxed);
                    }
                    index as u32
                })
            }),
    );
    (!out_of_range.into_inner()).then_some(indices)
}

#[cfg(test)]
mod tests {
    use super::super::{parse_header, read_body, Binary, Encoding};
    use super::*;

    /// A binary PLY made element by element.
    struct Ply {
        big_endian: bool,
        header: String,
        body: Vec<u8>,
    }

    impl Ply {
        fn new(big_endian: bool) -> Ply {
            let order = if big_endian { "big" } else { "little" };
            Ply {
                big_endian,
                header: format!("ply\nformat binary_{order}_endian 1.0\n"),
                body: Vec::new(),
            }
        }

        fn element(&mut self, name: &str, count: usize, properties: &[&str]) {
            self.header += &format!("element {name} {count}\n");
            for property in properties {
                self.header += &format!("property {property}\n");
            }
        }

        fn put(&mut self, ty: Scalar, value: f64) {
            let mut bytes = match ty {
                Scalar::I8 => (value as i8).to_le_bytes().to_vec(),
                Scalar::U8 => (value as u8).to_le_bytes().to_vec(),
                Scalar::I16 => (value as i16).to_le_bytes().to_vec(),
                Scalar::U16 => (value as u16).to_le_bytes().to_vec(),
                Scalar::I32 => (value as i32).to_le_bytes().to_vec(),
                Scalar::U32 => (value as u32).to_le_bytes().to_vec(),
                Scalar::F32 => (value as f32).to_le_bytes().to_vec(),
                Scalar::F64 => value.to_le_bytes().to_vec(),
            };
            if self.big_endian {
                bytes.reverse();
            }
            self.body.extend(bytes);
        }

        fn bytes(&self) -> Vec<u8> {
            let mut bytes = format!("{}end_header\n", self.header).into_bytes();
            bytes.extend(&self.body);
            bytes
        }
    }

    fn type_name(ty: Scalar) -> &'static str {
        match ty {
            Scalar::I8 => "char",
            Scalar::U8 => "uchar",
            Scalar::I16 => "short",
            Scalar::U16 => "ushort",
            Scalar::I32 => "int",
            Scalar::U32 => "uint",
            Scalar::F32 => "float",
            Scalar::F64 => "double",
        }
    }

    /// What the element-by-element reader makes of a binary file.
    fn general(data: &[u8], strict: bool) -> Result<MeshFile, IoError> {
        let (encoding, elements, body, _) = parse_header(data).unwrap();
        let Encoding::Binary { big_endian } = encoding else {
            panic!("a binary file");
        };
        let pos = data.len() - body.len();
        let mut source = Binary {
            data,
            pos,
            big_endian,
        };
        read_body(&mut source, &elements, strict, MeshOptions::default())
    }

    fn bulk(data: &[u8], strict: bool) -> Option<Result<MeshFile, IoError>> {
        let (encoding, elements, body, _) = parse_header(data).unwrap();
        let Encoding::Binary { big_endian } = encoding else {
            panic!("a binary file");
        };
        let at = data.len() - body.len();
        read_in_bulk(
            data,
            at,
            big_endian,
            &elements,
            strict,
            MeshOptions::default(),
        )
    }

    /// 90 vertices with colours, texture coordinates and properties of no
    /// role, faces of 3 to 9 corners between scalars of no role, and
    /// elements before and after; `edit` changes face 7's list.
    fn rich(
        big_endian: bool,
        length: Scalar,
        item: Scalar,
        edit: impl Fn(&mut Vec<f64>),
    ) -> Vec<u8> {
        let mut ply = Ply::new(big_endian);
        ply.element("camera", 2, &["float view_x", "double view_y"]);
        ply.element(
            "vertex",
            90,
            &[
                "float x",
                "double y",
                "short z",
                "int flags",
                "uchar red",
                "uchar green",
                "uchar blue",
                "float alpha",
                "float s",
                "double t",
            ],
        );
        let face_list = format!(
            "list {} {} vertex_indices",
            type_name(length),
            type_name(item)
        );
        ply.element("face", 20, &["uchar material", &face_list, "float quality"]);
        ply.element("edge", 3, &["int vertex1", "int vertex2"]);
        for k in 0..2 {
            ply.put(Scalar::F32, k as f64);
            ply.put(Scalar::F64, 0.5);
        }
        for v in 0..90 {
            let a = v as f64 * 0.7;
            ply.put(Scalar::F32, a.cos() * 3.25);
            ply.put(Scalar::F64, a.sin() / 3.0);
            ply.put(Scalar::I16, (v % 7) as f64 - 3.0);
            ply.put(Scalar::I32, -(v as f64));
            for channel in 0..3 {
                ply.put(Scalar::U8, ((v * 37 + channel * 91) % 256) as f64);
            }
            ply.put(Scalar::F32, 0.25);
            ply.put(Scalar::F32, v as f64 / 90.0);
            ply.put(Scalar::F64, 1.0 - v as f64 / 90.0);
        }
        let mut next = 0;
        for f in 0..20 {
            let mut corners: Vec<f64> = (0..3 + f % 7).map(|k| ((next + k) % 90) as f64).collect();
            next += corners.len();
            if f == 7 {
                edit(&mut corners);
            }
            ply.put(Scalar::U8, f as f64);
            ply.put(length, corners.len() as f64);
            for &c in &corners {
                ply.put(item, c);
            }
            ply.put(Scalar::F32, 0.125 * f as f64);
        }
        for e in 0..3 {
            ply.put(Scalar::I32, e as f64);
            ply.put(Scalar::I32, e as f64 + 1.0);
        }
        ply.bytes()
    }

    #[test]
    fn layouts_are_read_in_bulk_as_element_by_element() {
        let types = [
            (Scalar::U8, Scalar::I32),
            (Scalar::U8, Scalar::U32),
            (Scalar::U16, Scalar::U8),
            (Scalar::I32, Scalar::I16),
            (Scalar::I8, Scalar::U16),
        ];
        for big_endian in [false, true] {
            for (length, item) in types {
                let data = rich(big_endian, length, item, |_| {});
                for strict in [false, true] {
                    let expected = general(&data, strict).unwrap();
                    let read = bulk(&data, strict).expect("read in bulk").unwrap();
                    assert_eq!(read, expected, "{big_endian} {length:?} {item:?}");
                    assert!(read.colours.is_some() && read.uvs.is_some());
                    assert_eq!(read.mesh.face_count(), 20);
                }
            }
        }
    }

    #[test]
    fn files_it_does_not_take_go_to_the_general_reader() {
        let cut = {
            let mut data = rich(false, Scalar::U8, Scalar::I32, |_| {});
            data.truncate(data.len() - 30);
            data
        };
        let empty_face = rich(false, Scalar::I8, Scalar::I32, |corners| corners.clear());
        let negative_length = {
            let mut ply = Ply::new(false);
            ply.element("vertex", 3, &["float x", "float y", "float z"]);
            ply.element("face", 1, &["list char int vertex_indices"]);
            (0..9).for_each(|c| ply.put(Scalar::F32, c as f64));
            ply.put(Scalar::I8, -1.0);
            [0.0, 1.0, 2.0]
                .iter()
                .for_each(|&v| ply.put(Scalar::I32, v));
            ply.bytes()
        };
        let negative_index = rich(true, Scalar::U8, Scalar::I32, |corners| corners[1] = -4.0);
        for data in [cut, negative_index, negative_length] {
            assert!(bulk(&data, true).is_none());
            let error = crate::io::ply::parse_file(&data).unwrap_err().to_string();
            assert_eq!(error, general(&data, true).unwrap_err().to_string());
        }
        // A length of 0 is a face the mesh refuses, named where it starts.
        let expected = general(&empty_face, true).unwrap_err().to_string();
        let read = bulk(&empty_face, true).expect("read in bulk");
        assert_eq!(read.unwrap_err().to_string(), expected);
        assert!(expected.contains("byte"), "{expected}");

        // A second list: read element by element, not refused.
        let mut ply = Ply::new(false);
        ply.element("vertex", 3, &["float x", "float y", "float z"]);
        ply.element(
            "face",
            1,
            &["list uchar int vertex_indices", "list uchar float texcoord"],
        );
        for v in [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]] {
            v.iter().for_each(|&c| ply.put(Scalar::F32, c));
        }
        ply.put(Scalar::U8, 3.0);
        [0.0, 1.0, 2.0]
            .iter()
            .for_each(|&v| ply.put(Scalar::I32, v));
        ply.put(Scalar::U8, 2.0);
        [0.5, 0.5].iter().for_each(|&t| ply.put(Scalar::F32, t));
        let data = ply.bytes();
        assert!(bulk(&data, true).is_none());
        assert_eq!(
            crate::io::ply::parse_file(&data).unwrap(),
            general(&data, true).unwrap()
        );
    }

    #[test]
    fn a_colour_that_is_not_finite_is_refused_only_when_strict() {
        let mut ply = Ply::new(false);
        ply.element(
            "vertex",
            3,
            &[
                "float x",
                "float y",
                "float z",
                "float red",
                "float green",
                "float blue",
            ],
        );
        ply.element("face", 1, &["list uchar int vertex_indices"]);
        for v in 0..3 {
            for c in [v as f64, (v * v) as f64, 1.0, 0.5, f64::NAN, 0.25] {
                ply.put(Scalar::F32, c);
            }
        }
        ply.put(Scalar::U8, 3.0);
        [0.0, 1.0, 2.0]
            .iter()
            .for_each(|&v| ply.put(Scalar::I32, v));
        let data = ply.bytes();
        assert!(bulk(&data, true).is_none());
        let strict = crate::io::ply::parse_file(&data).unwrap_err().to_string();
        assert_eq!(strict, general(&data, true).unwrap_err().to_string());
        assert!(strict.contains("colour of vertex 0"), "{strict}");
        let lenient = bulk(&data, false).expect("read in bulk").unwrap();
        assert_eq!(lenient.mesh, general(&data, false).unwrap().mesh);
    }

    #[test]
    fn an_index_past_the_vertices_is_named_at_its_face() {
        let data = rich(false, Scalar::U8, Scalar::U32, |corners| corners[2] = 90.0);
        let expected = general(&data, true).unwrap_err();
        let read = bulk(&data, true).expect("read in bulk").unwrap_err();
        assert_eq!(read.to_string(), expected.to_string());
        assert_eq!(read.location(), expected.location());
    }
}
