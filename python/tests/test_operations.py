"""Each operation through its Python function: shapes and counts of the
results, the options, and every error path (wrong type, value or option,
and what the library refuses)."""

import numpy as np
import pytest

import weft
from conftest import same_bits

ALL_THREE = ["fixed", "smooth", "corner-fixed"]


def test_catmull_clark_counts_and_order(mixed):
    s = weft.catmull_clark(mixed, levels=1)
    info = mixed.info()
    assert s.vertex_count == mixed.vertex_count + info.edge_count + mixed.face_count
    assert s.face_count == mixed.index_count and (s.face_sizes == 4).all()
    assert same_bits(s.vertices[:0], mixed.vertices[:0])
    assert weft.catmull_clark(mixed, levels=0) == mixed


def test_naked_edge_modes_differ_on_an_open_mesh(cage):
    results = [weft.catmull_clark(cage, levels=1, naked_edges=mode) for mode in ALL_THREE]
    assert results[0] != results[1] and results[1] != results[2]
    assert weft.catmull_clark(cage, naked_edges="CORNER_FIXED") == results[2]


def test_loop_needs_triangles(mixed):
    with pytest.raises(weft.WeftError) as caught:
        weft.loop(mixed)
    assert caught.value.status == weft.Status.NOT_TRIANGLES and "face 0" in caught.value.message
    assert weft.loop(weft.platonic("icosahedron"), levels=1).face_count == 80


@pytest.mark.parametrize(
    "call, error, words",
    [
        (lambda m: weft.catmull_clark(m, naked_edges="round"), ValueError, "naked_edges is 'round'"),
        (lambda m: weft.catmull_clark(m, naked_edges=1), ValueError, "naked_edges"),
        (lambda m: weft.catmull_clark(m, levels=-1), ValueError, "levels is -1"),
        (lambda m: weft.catmull_clark(m, levels=1.5), TypeError, "levels must be an integer"),
        (lambda m: weft.catmull_clark(m, levels=True), TypeError, "levels"),
        (lambda m: weft.catmull_clark([[0, 1, 2]]), TypeError, "mesh must be a weft.Mesh"),
        (lambda m: weft.subdivide(m, scheme="doo-sabin"), ValueError, "scheme is 'doo-sabin'"),
        (lambda m: weft.subdivide(m, creasing="sharp"), ValueError, "creasing"),
        (lambda m: weft.subdivide(m, creases=[(0, 1)]), ValueError, "creases must have shape"),
        (lambda m: weft.subdivide(m, creases=[(0.5, 1, 2.0)]), ValueError, "creases: vertex indices must be whole"),
        (lambda m: weft.subdivide(m, corners=[(0, 1, 2)]), ValueError, "corners must have shape"),
        (lambda m: weft.weld(m, tolerance="small"), TypeError, "tolerance must be a number"),
        (lambda m: weft.platonic("cube"), ValueError, "kind is 'cube'"),
        (lambda m: weft.tile(m, fill="weave"), ValueError, "fill"),
        (lambda m: weft.delaunay([[0, 0], [1, 0], [0, 1]]), ValueError, "points must have shape"),
        (lambda m: weft.delaunay(np.random.rand(5, 3), plane=[(0, 0, 0), (1, 0, 0)]), ValueError, "plane"),
        (lambda m: weft.delaunay(np.random.rand(5, 3), plane=[(0, 0, 0), (1, 0), (0, 1, 0)]), ValueError, "plane\\[1\\]"),
        (lambda m: weft.Refiner(m).evaluate(np.zeros((2, 3))), weft.WeftError, "vertex"),
        (lambda m: weft.Refiner(m).evaluate(m.vertices, out=np.zeros((3, 3))), ValueError, "out must have shape"),
        (lambda m: weft.Refiner(m).evaluate(m.vertices, out=[1]), TypeError, "out must be"),
        (lambda m: weft.reroute_faces(m, 0.5), TypeError, "shift"),
        (lambda m: weft.blur_values(m, np.zeros((2, 2, 2))), ValueError, "values must have shape"),
        (lambda m: weft.mesh_from_grid(np.zeros((12, 3))), ValueError, "u_count and v_count"),
        (lambda m: weft.join([m, "box"]), TypeError, "meshes\\[1\\] must be a weft.Mesh"),
        (lambda m: weft.read(42), TypeError, "path must be"),
    ],
)
def test_wrong_arguments_name_themselves(call, error, words, cage):
    with pytest.raises(error, match=words):
        call(cage)


@pytest.mark.parametrize(
    "call, status, words",
    [
        (lambda m: weft.subdivide(m, creases=[(0, 30, 10.0)]), weft.Status.INVALID_ARGUMENT, "crease"),
        (lambda m: weft.subdivide(m, corners=[(999, 10.0)]), weft.Status.INVALID_ARGUMENT, "999"),
        (lambda m: weft.subdivide(m, creases=[(0, 1, -1.0)]), weft.Status.INVALID_ARGUMENT, "sharpness"),
        (lambda m: weft.catmull_clark(m, levels=40), weft.Status.RESULT_TOO_LARGE, ""),
        (lambda m: weft.weld(m, tolerance=-1.0), weft.Status.INVALID_ARGUMENT, "tolerance"),
        (lambda m: weft.find_t_nodes(m, np.nan), weft.Status.INVALID_ARGUMENT, "tolerance"),
        (lambda m: weft.delaunay([[0, 0, 0], [1, 0, 0], [2, 0, 0]]), weft.Status.DEGENERATE_INPUT, "collinear"),
        (lambda m: weft.delaunay([[0, 0, 0], [1, 0, 0], [np.nan, 1, 0]]), weft.Status.NON_FINITE_COORDINATE, "point 2"),
        (lambda m: weft.voronoi(np.random.rand(5, 3), radius=-1.0), weft.Status.INVALID_ARGUMENT, "radius"),
        (lambda m: weft.stellate(m, [1.0, 2.0]), weft.Status.INVALID_ARGUMENT, "2"),
        (lambda m: weft.inner_polygons(m, pull=1.5), weft.Status.INVALID_ARGUMENT, "pull"),
        (lambda m: weft.laplacian_hc_smooth(m, activation=[0.5]), weft.Status.INVALID_ARGUMENT, "activation"),
        (lambda m: weft.split_triangles(m), weft.Status.NOT_TRIANGLES, "face 0"),
        (lambda m: weft.mesh_from_grid(np.zeros((12, 3)), 5, 3), weft.Status.INVALID_ARGUMENT, "5"),
        (lambda m: weft.box(-1.0), weft.Status.INVALID_ARGUMENT, ""),
        (lambda m: weft.subdivide_vertex_data(m, np.full(m.vertex_count, np.nan)), weft.Status.INVALID_ARGUMENT, "vertex"),
    ],
)
def test_what_the_library_refuses_raises_weft_error(call, status, words, cage):
    with pytest.raises(weft.WeftError) as caught:
        call(cage)
    assert caught.value.status == status, caught.value
    assert words in caught.value.message


def test_subdivide_with_creases_keeps_a_hard_crease_sharper(cage):
    edge = weft.edges(cage)[5]
    plain = weft.subdivide(cage, levels=2, naked_edges="smooth")
    creased = weft.subdivide(cage, levels=2, naked_edges="smooth", creases=[(int(edge[0]), int(edge[1]), weft.SHARPNESS_INFINITE)])
    cornered = weft.subdivide(cage, levels=2, naked_edges="smooth", corners=np.array([[int(edge[0]), np.inf]]))
    assert plain != creased and plain != cornered
    assert creased.face_count == plain.face_count
    # A corner of infinite sharpness does not move.
    assert same_bits(cornered.vertices[edge[0]], cage.vertices[edge[0]])


def test_refiner_evaluates_new_positions_like_a_new_subdivision(cage):
    r = weft.Refiner(cage, levels=3, naked_edges="smooth")
    moved = np.array(cage.vertices) * 2.0 + 1.0
    expected = weft.catmull_clark(weft.Mesh(moved, cage.faces), levels=3, naked_edges="smooth")
    assert same_bits(r.evaluate(moved), expected.vertices)
    buffer = np.empty((r.vertex_count, 3))
    assert r.evaluate(moved, out=buffer) is buffer
    assert r.face_count == expected.face_count and "Refiner" in repr(r)
    creased = weft.Refiner(cage, levels=1, creases=[(0, 1, 10.0)])
    assert same_bits(creased.mesh.vertices, weft.subdivide(cage, levels=1, creases=[(0, 1, 10.0)]).vertices)


def test_subdivision_queries(cage):
    counts = weft.subdivision_counts(cage, levels=2)
    s = weft.catmull_clark(cage, levels=2)
    assert counts == (s.vertex_count, s.face_count, s.index_count)
    assert weft.subdivision_face_count(cage, levels=2) == s.face_count
    parents = weft.subdivision_parent_faces(cage, levels=1)
    assert parents.tolist() == np.repeat(np.arange(cage.face_count), 4).tolist()


def test_holes_boundary_none_and_smooth_triangles(cage):
    plain = weft.subdivide(cage, levels=2, naked_edges="smooth")
    holed = weft.subdivide(cage, levels=2, naked_edges="smooth", holes=[1, 4])
    assert same_bits(holed.vertices, plain.vertices)
    lost = sum(len(cage.faces[f]) * 4 for f in (1, 4))
    assert holed.face_count == plain.face_count - lost
    counts = weft.subdivision_counts(cage, levels=2, naked_edges="smooth", holes=[1, 4])
    assert counts == (holed.vertex_count, holed.face_count, holed.index_count)
    parents = weft.subdivision_parent_faces(cage, levels=2, naked_edges="smooth", holes=[1, 4])
    assert len(parents) == holed.face_count and not set(parents.tolist()) & {1, 4}
    uvs = weft.subdivide_face_varying(cage, np.array(cage.vertices)[:, :2], cage.face_indices, levels=2,
                                      naked_edges="smooth", holes=[1, 4])
    assert uvs.shape == (holed.index_count, 2)
    r = weft.Refiner(cage, levels=2, naked_edges="smooth", holes=[1, 4])
    assert r.face_count == holed.face_count
    n = cage.face_count
    with pytest.raises(weft.WeftError, match=f"hole 0 is face {n}, but the mesh has {n} faces"):
        weft.subdivide(cage, holes=[n])
    # A closed box has no boundary: none keeps every face.
    assert weft.catmull_clark(weft.box(), levels=1, naked_edges="none").face_count == 24
    grid = weft.Mesh([[x, y, 0] for y in range(3) for x in range(3)], [[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6], [4, 5, 8, 7]])
    assert weft.catmull_clark(grid, levels=1, naked_edges="none").face_count == 0
    with pytest.raises(weft.WeftError, match="only subdivision makes"):
        weft.laplacian_smooth(grid, naked_edges="none")
    prism = weft.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [0, 1, 1]],
                      [[0, 2, 1], [3, 4, 5], [0, 1, 4, 3], [1, 2, 5, 4], [2, 0, 3, 5]])
    smooth = weft.subdivide(prism, levels=1, triangles="smooth")
    catmark = weft.subdivide(prism, levels=1)
    assert not np.array_equal(smooth.vertices, catmark.vertices)
    with pytest.raises(ValueError, match="triangles"):
        weft.subdivide(prism, triangles="round")


def test_vertex_data_follows_the_positions(cage):
    data = np.array(cage.vertices)
    carried = weft.subdivide_vertex_data(cage, data, levels=2, naked_edges="smooth", creases=[(0, 1, 2.0)])
    assert same_bits(carried, weft.subdivide(cage, levels=2, naked_edges="smooth", creases=[(0, 1, 2.0)]).vertices)
    single = weft.subdivide_vertex_data(cage, data[:, 0], levels=1)
    assert single.shape == (weft.subdivision_counts(cage)[0],)


def test_face_varying_values_and_limit(cage):
    values = np.array(cage.vertices)[:, :2]
    per_corner = weft.subdivide_face_varying(cage, values, cage.face_indices, levels=1, linear="all")
    assert per_corner.shape == (weft.subdivision_counts(cage)[2], 2)
    points, normals = weft.subdivide_limit(weft.box(), levels=1)
    assert points.shape == normals.shape == (26, 3)
    assert np.allclose(np.linalg.norm(normals, axis=1), 1.0)


def test_crease_edges_from_mesh():
    square = weft.plane_grid(1, 1)
    unwelded = weft.join([square, weft.Mesh(np.array(square.vertices) + [1.0, 0, 0], square.faces)])
    welded, pairs = weft.crease_edges_from_mesh(unwelded, 180.0)
    assert welded.vertex_count == 6 and pairs.shape == (1, 2)
    welded_too, pairs_too, vertex_map = weft.crease_edges_from_mesh(unwelded, 180.0, vertex_map=True)
    assert welded_too == welded and same_bits(pairs_too, pairs)
    assert vertex_map.shape == (8,) and vertex_map.max() == 5


def test_weld_join_and_report():
    a = weft.box()
    b = weft.Mesh(np.array(a.vertices) + [1.0, 0, 0], a.faces)
    joined = weft.join([a, b])
    assert joined.vertex_count == 16 and weft.join([]).vertex_count == 0
    welded, report = weft.weld([a, b], tolerance=1e-6)
    assert welded.vertex_count == 12 and report.merged_vertex_count == 4
    assert weft.weld(joined, 1e-6)[0] == welded
    culled, removed = weft.cull_adjacent(welded, report=True)
    assert removed == 2 and culled.face_count == 10 and culled.info().is_closed
    assert weft.cull_adjacent(welded) == culled


def test_t_nodes():
    coarse = weft.plane_grid(2, 2, 1, 1)
    fine = weft.plane_grid(2, 2, 2, 2)
    joined, _ = weft.weld([coarse, weft.Mesh(np.array(fine.vertices) + [2.0, 0, 0], fine.faces)], 1e-9)
    nodes = weft.find_t_nodes(joined, 1e-6)
    assert nodes.dtype == weft.TNODE_DTYPE and len(nodes) == 1
    assert nodes[0]["face"] == 0 and nodes[0]["parameter"] == pytest.approx(0.5)
    assert same_bits(joined.vertices[nodes[0]["vertex"]], np.array([1.0, 0.0, 0.0]))
    repaired, inserted = weft.repair_t_nodes(joined, 1e-6, report=True)
    assert inserted == 1 and repaired.index_count == joined.index_count + 1
    assert len(weft.find_t_nodes(repaired, 1e-6)) == 0 and len(weft.find_t_nodes(weft.box())) == 0


def test_orientation():
    a = weft.box()
    assert weft.flip(weft.flip(a)) == a
    assert weft.flip(a).faces[0] == [a.faces[0][0]] + a.faces[0][:0:-1]
    broken = weft.Mesh(a.vertices, [a.faces[0][::-1]] + a.faces[1:])
    fixed, flipped = weft.unify(broken, report=True)
    assert flipped == 1 and fixed.info().is_oriented and weft.unify_orientation(broken) == fixed


def test_normals_planarity_edges_and_boundaries(cage):
    box = weft.box(2, 2, 2)
    normals = weft.face_normals(box)
    assert normals.shape == (6, 3) and np.allclose(np.abs(normals).sum(axis=1), 1.0)
    assert weft.vertex_normals(box).shape == (8, 3)
    assert (weft.planarity(box) == 0).all() and (weft.planarity(cage) > 0).any()
    assert weft.edges(box).shape == (12, 2) and weft.edge_segments(box).shape == (12, 2, 3)
    ((points, closed),) = weft.naked_boundaries(weft.plane_grid(1, 1, 2, 2))
    assert points.shape == (8, 3) and closed
    assert weft.naked_boundaries(box) == []


def test_delaunay_and_voronoi():
    rng = np.random.default_rng(2)
    points = rng.uniform(0, 10, (40, 3))
    mesh = weft.delaunay(np.vstack([points, points[:3]]))
    assert mesh.vertex_count == 40 and (mesh.face_sizes == 3).all()
    tilted = weft.delaunay(points, plane=((0, 0, 0), (1, 0, 0), (0, 0, 1)))
    assert tilted.face_count > 0
    cells = weft.voronoi(points, radius=3.0)
    assert len(cells) == 40 and cells.sizes.sum() == len(cells.corners)
    assert same_bits(cells[1], cells.corners[cells.sizes[0] : cells.sizes[0] + cells.sizes[1]])
    sizes, corners = cells.copy_arrays()
    assert same_bits(sizes, cells.sizes) and same_bits(corners, cells.corners)
    skin = cells.to_mesh()
    assert skin.face_count == 40 and "40 cells" in repr(cells)
    bounded = weft.voronoi(points, boundary=[(0, 0, 0), (5, 0, 0), (5, 5, 0), (0, 5, 0)])
    assert (bounded.sizes == 0).any()


def test_makers():
    assert weft.plane_grid(2, 1, 4, 2).face_count == 8
    assert weft.box(1, 1, 1, 2, 2, 2).face_count == 24
    assert weft.uv_sphere(1.0, 8, 4).info().is_closed
    assert [weft.platonic(k).face_count for k in weft._ops.PLATONIC] == [4, 6, 8, 12, 20]
    assert weft.sided_solid("prism", 6).face_count == 8
    grid = weft.mesh_from_grid(np.random.rand(3, 4, 3))
    assert grid.face_count == 6 and weft.mesh_from_grid(np.random.rand(12, 3), 4, 3, triangulate=True).face_count == 12
    assert weft.stellate(weft.box(), 0.5).face_count == 24
    assert weft.stellate(weft.box(), np.arange(6.0) * 0.1).vertex_count == 14
    square = [[(0, 0, 0), (1, 0, 0)], [(1, 0, 0), (1, 1, 0)], [(1, 1, 0), (0, 1, 0)], [(0, 1, 0), (0, 0, 0)]]
    assert weft.mesh_from_lines(square).faces == [[0, 1, 2, 3]] or weft.mesh_from_lines(square).face_count == 1
    assert weft.mesh_from_lines(np.array(square).reshape(4, 6)).face_count == 1


def test_toolbar(cage, pentagon_mesh):
    box = weft.box()
    assert weft.triangulate(pentagon_mesh).face_count == 5
    assert weft.split_polygons(box, 1).face_count == 24
    assert weft.split_triangles(weft.triangulate(box), 1).face_count == 48
    assert weft.constant_quads_split(box, 1).face_count == 24
    assert weft.midedge(box, 1).face_count > 0
    assert weft.inner_polygons(box, 1, 0.3).face_count == 30
    assert weft.sierpinski_triangles(weft.triangulate(box), 1).face_count == 36
    assert weft.sierpinski_carpet(box, 1).face_count == 48
    smooth = weft.laplacian_smooth(cage, 3, 0.5, "smooth")
    assert smooth.face_count == cage.face_count and smooth != cage
    hc = weft.laplacian_hc_smooth(cage, 3)
    assert hc != cage
    anchored = weft.laplacian_hc_smooth(cage, 3, activation=np.zeros(cage.vertex_count))
    assert same_bits(anchored.vertices, cage.vertices)
    assert weft.laplacian_hc_smooth(cage, 3, direction="along-normal") != hc
    blurred = weft.blur_values(cage, np.arange(cage.vertex_count, dtype=float), 2)
    assert blurred.shape == (cage.vertex_count,)
    assert weft.blur_values(cage, np.ones((cage.vertex_count, 3)), 2).shape == (cage.vertex_count, 3)
    assert weft.offset_mesh(box, 0.1).vertex_count == 8
    assert weft.thicken_mesh(weft.plane_grid(), 0.1).face_count == 6
    assert weft.mesh_window(box, 0.2).face_count == 30
    assert weft.picture_frame(box, [0.1] * 6, "edge-fraction").face_count == 24
    assert weft.bevel_edges(box, 0.3).face_count == 26
    assert weft.bevel_vertices(box, 0.3).face_count == 14
    assert weft.dual(box).face_count == 8 and weft.dual(box, "keep-size").face_count == 8
    assert weft.reroute_faces(box, 1).faces[0] == box.faces[0][1:] + box.faces[0][:1]
    assert weft.tile(box, "triangle-fan", "quads").face_count == 24
    assert weft.version() == weft.__version__


def test_limit_patches_are_the_c_abis_and_exact_away_from_corners():
    cube = weft.box(1, 1, 1)
    control, faces, errors = weft.limit_patches(cube, isolation=2, naked_edges="smooth")
    assert control.shape == (96, 4, 4, 3) and faces.dtype == np.uint32
    assert faces.tolist() == np.repeat(np.arange(6), 16).tolist()
    # Three patches touch each of the 8 corners; the others are the limit to rounding.
    assert int((errors < 1e-12).sum()) == 72 and errors.max() > 1e-4
    # Corner (0, 0) of each patch is the limit point of its face's first corner.
    points, _ = weft.subdivide_limit(cube, levels=2, naked_edges="smooth")
    refined = weft.subdivide(cube, levels=2, naked_edges="smooth")
    first = refined.face_indices.reshape(-1, 4)[:, 0]
    assert np.abs(control[:, 0, 0] - points[first]).max() < 1e-14
    with pytest.raises(weft.WeftError, match="isolation is 0"):
        weft.limit_patches(cube, isolation=0)
    # The same patches from the surface object.
    again = weft.LimitSurface(cube, naked_edges="smooth").patches(2)
    assert all(np.array_equal(a, b) for a, b in zip(again, (control, faces, errors)))
    with pytest.raises(weft.WeftError, match="CATMULL_CLARK"):
        weft.LimitSurface(weft.triangulate(cube), scheme="loop").patches(1)


@pytest.mark.parametrize("scheme, naked_edges", [("catmull-clark", "smooth"), ("catmull-clark", "none"), ("loop", "fixed")])
def test_subdivide_into_equals_the_new_mesh(mixed, scheme, naked_edges):
    cage = mixed if scheme == "catmull-clark" else weft.triangulate(mixed)
    for levels in range(3):
        subdivide = weft.catmull_clark if scheme == "catmull-clark" else weft.loop
        expected = subdivide(cage, levels=levels, naked_edges=naked_edges)
        n, f, k = weft.subdivision_counts(cage, scheme, levels, naked_edges)
        positions = np.full((n + 2, 3), -7.0)
        indices = np.full(k + 3, 99, dtype=np.uint32)
        assert weft.subdivide_into(cage, positions, indices, scheme, levels, naked_edges) is None
        assert same_bits(positions[: expected.vertex_count], expected.vertices)
        assert (indices[: expected.index_count] == expected.face_indices).all()
        assert (positions[expected.vertex_count :] == -7.0).all() and (indices[expected.index_count :] == 99).all()


def test_subdivide_into_refuses_what_it_cannot_write(mixed):
    n, f, k = weft.subdivision_counts(mixed, levels=2)
    positions, quads = np.zeros((n, 3)), np.zeros((f, 4), dtype=np.uint32)
    short = np.zeros((n - 1, 3))
    with pytest.raises(weft.WeftError) as caught:
        weft.subdivide_into(mixed, short, quads, levels=2)
    assert caught.value.status == weft.Status.BUFFER_TOO_SMALL and f"room for {n - 1} vertices" in caught.value.message
    assert (short == 0).all() and (quads == 0).all()
    with pytest.raises(TypeError, match="positions must hold float64, not float32"):
        weft.subdivide_into(mixed, positions.astype(np.float32), quads, levels=2)
    with pytest.raises(TypeError, match="face_indices must hold uint32, not int64"):
        weft.subdivide_into(mixed, positions, quads.astype(np.int64), levels=2)
    with pytest.raises(TypeError, match="positions must be a numpy array"):
        weft.subdivide_into(mixed, [[0.0, 0.0, 0.0]] * n, quads, levels=2)
    with pytest.raises(ValueError, match=r"positions must have shape \(n, 3\)"):
        weft.subdivide_into(mixed, positions.reshape(-1), quads, levels=2)
    with pytest.raises(ValueError, match="C-contiguous and writable"):
        weft.subdivide_into(mixed, np.zeros((n, 6))[:, :3], quads, levels=2)
    positions.flags.writeable = False
    with pytest.raises(ValueError, match="C-contiguous and writable"):
        weft.subdivide_into(mixed, positions, quads, levels=2)
    with pytest.raises(ValueError, match="naked_edges"):
        weft.subdivide_into(mixed, np.zeros((n, 3)), quads, levels=2, naked_edges="round")
