using System;

namespace Weft.Tests
{
    /// <summary>Creases, corners, carried data, face-varying values, the limit surface, the refiner with options and creases found on a mesh.</summary>
    public static class CreaseTests
    {
        private static Runner t;

        // The four edges of the cube's bottom face (face 0, z = 0).
        private static readonly uint[] BottomLoop = { 0, 2, 2, 3, 3, 1, 1, 0 };

        public static void Register(Runner runner)
        {
            t = runner;
            t.Run("a hard crease loop keeps the cube's bottom in its plane and its edge point on the edge line", HardCreaseLoop);
            t.Run("an infinitely sharp corner stays exactly at its cage position", SharpCornerStays);
            t.Run("sharpness 0 is the plain scheme; semi-sharp lies between smooth and hard; Chaikin differs", SemiSharp);
            t.Run("Loop with a hard corner on the octahedron", LoopCorner);
            t.Run("counts equal the subdivided mesh's counts", CountsMatch);
            t.Run("vertex data equal to the positions gives the refined positions", VertexDataIsPositions);
            t.Run("face-varying values without seams equal the refined vertex values", FaceVaryingWithoutSeams);
            t.Run("limit surface: corner kept, unit outward normals, normals optional", LimitSurface);
            t.Run("limit surface anywhere: corners are the vertex limit, closest points lie on it", LimitSurfaceAnywhere);
            t.Run("refiner with creases re-evaluated equals a fresh creased subdivision", RefinerWithOptions);
            t.Run("crease edges from an unwelded cube: welded, 12 creases, stays a cube", CreaseEdgesFromUnweldedCube);
            t.Run("crease edges from folds by angle", CreaseEdgesByAngle);
            t.Run("crease edges' vertex map takes each input vertex to the welded one at its place", CreaseEdgesVertexMap);
            t.Run("options: copies, comparison and chaining", OptionsValue);
            t.Run("crease and corner errors name the crease or corner", CreaseErrors);
            t.Run("carried data errors: lengths, widths, small buffers, unknown values", DataErrors);
            t.Run("disposed and null meshes are refused", DisposedMesh);
            t.Run("holes leave their faces out, keep their vertices, and the counts and parents agree", Holes);
            t.Run("naked edges none and smooth triangles reach the library; bad values are named", NoneAndTriangles);
            t.Run("limit patches: one per refined face, corners on the limit, exact away from the cube's corners", LimitPatchesOfCube);
        }

        private static void LimitPatchesOfCube()
        {
            var options = new SubdivisionOptions(NakedEdges.Smooth);
            using (var cube = Shapes.Cube())
            using (var refined = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, options))
            {
                LimitPatches patches = Subdivision.LimitPatches(cube, options, 2);
                t.Equal(96, patches.Count, "patches");
                t.Equal(48 * 96, patches.ControlPoints.Length, "control points");
                int exact = 0;
                foreach (double e in patches.Errors) if (e < 1e-12) exact++;
                t.Equal(72, exact, "exact patches: all but the 3 at each of the 8 corners");
                t.Equal(72, patches.ExactCount, "the library's count of exact patches");
                t.True(patches.MaxError > 1e-4 && patches.MaxError < 1e-2, "the corners' error: " + patches.MaxError);
                t.Equal(5u, patches.CageFaces[95], "the last patch lies on face 5");
                // Corner (0, 0) of patch p is the limit point of refined face p's first corner.
                LimitSurface limit = Subdivision.SubdivideLimit(cube, Scheme.CatmullClark, 2, options);
                uint[] corners = refined.GetFaceIndices();
                double worst = 0;
                for (int p = 0; p < 96; p++)
                    for (int k = 0; k < 3; k++)
                        worst = Math.Max(worst, Math.Abs(patches.ControlPoints[48 * p + k] - limit.Positions[3 * corners[4 * p] + k]));
                t.True(worst < 1e-14, "patch corners on the limit: " + worst);
                try
                {
                    Subdivision.LimitPatches(cube, options, 0);
                    t.True(false, "isolation 0 was accepted");
                }
                catch (WeftException e)
                {
                    t.Equal(WeftStatus.InvalidArgument, e.Status, "isolation 0");
                }
            }
        }

        private static SubdivisionOptions Hard(uint[] pairs)
        {
            return new SubdivisionOptions(NakedEdges.Smooth).AddCreases(pairs, SubdivisionOptions.SharpnessInfinite);
        }

        private static int CountZ(double[] positions, double z)
        {
            int count = 0;
            for (int i = 2; i < positions.Length; i += 3)
            {
                if (positions[i] == z) count++;
            }
            return count;
        }

        private static void HardCreaseLoop()
        {
            using (var cube = Shapes.Cube())
            using (var once = Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, Hard(BottomLoop)))
            using (var twice = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, Hard(BottomLoop)))
            using (var smooth = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, new SubdivisionOptions(NakedEdges.Smooth)))
            {
                t.Equal(26, once.VertexCount, "vertices after one level");
                double[] p = once.GetPositions();
                // The face inside the loop stays flat: 4 cage vertices, 4 edge points and its face point at
                // level 1, its 5 × 5 grid at level 2, exactly at z = 0; nothing else.
                t.Equal(9, CountZ(p, 0.0), "level-1 vertices exactly at z = 0");
                t.Equal(25, CountZ(twice.GetPositions(), 0.0), "level-2 vertices exactly at z = 0");
                t.Equal(0, CountZ(smooth.GetPositions(), 0.0), "uncreased level-2 vertices at z = 0");
                // Vertex 0 follows its crease: 3/4 itself + 1/8 of each crease neighbour.
                Shapes.Near(new[] { 0.125, 0.125, 0.0 }, Shapes.Vertex(once, 0), 1e-12, "crease vertex 0");
                // The hard edge (0, 1)'s edge point is its midpoint, on the edge line y = z = 0.
                bool found = false;
                for (int v = 8; v < 20; v++)
                {
                    if (p[3 * v] == 0.5 && p[3 * v + 1] == 0.0 && p[3 * v + 2] == 0.0) found = true;
                }
                t.True(found, "an edge point at (0.5, 0, 0)");
            }
        }

        private static void SharpCornerStays()
        {
            var options = new SubdivisionOptions(NakedEdges.Smooth).AddCorner(7, SubdivisionOptions.SharpnessInfinite);
            using (var cube = Shapes.Cube())
            using (var refined = Subdivision.Subdivide(cube, Scheme.CatmullClark, 3, options))
            using (var plain = Subdivision.CatmullClark(cube, 3, NakedEdges.Smooth))
            {
                t.Sequence(new[] { 1.0, 1.0, 1.0 }, Shapes.Vertex(refined, 7), "vertex 7 exactly at its cage position");
                t.True(Shapes.Vertex(plain, 7)[0] < 0.9, "without the corner vertex 7 moves in");
                // Infinity is as hard as 10.
                var infinite = new SubdivisionOptions(NakedEdges.Smooth).AddCorner(7, double.PositiveInfinity);
                using (var same = Subdivision.Subdivide(cube, Scheme.CatmullClark, 3, infinite))
                {
                    t.Sequence(refined.GetPositions(), same.GetPositions(), "infinity equals 10");
                }
            }
        }

        private static void SemiSharp()
        {
            using (var cube = Shapes.Cube())
            {
                var zero = new SubdivisionOptions(NakedEdges.Smooth).AddCreases(BottomLoop, 0).AddCorner(7, 0);
                using (var a = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, zero))
                using (var b = Subdivision.CatmullClark(cube, 2, NakedEdges.Smooth))
                {
                    Shapes.Near(b.GetPositions(), a.GetPositions(), 1e-12, "sharpness 0");
                    t.Sequence(b.GetFaceIndices(), a.GetFaceIndices(), "same faces");
                }
                var semi = new SubdivisionOptions(NakedEdges.Smooth).AddCreases(BottomLoop, 1.5);
                using (var s = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, semi))
                using (var hard = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, Hard(BottomLoop)))
                using (var soft = Subdivision.CatmullClark(cube, 2, NakedEdges.Smooth))
                {
                    double zs = Shapes.Vertex(s, 0)[2], zh = Shapes.Vertex(hard, 0)[2], zp = Shapes.Vertex(soft, 0)[2];
                    t.True(zh < zs && zs < zp, "vertex 0's height between hard and smooth: " + zh + " < " + zs + " < " + zp);
                }
                // Different sharpness along the loop: Chaikin averages it, Uniform does not, so the
                // 1.8 edges are 0.8 sharp at level 1 with Uniform and 0.475 with Chaikin.
                var uniform = new SubdivisionOptions(NakedEdges.Smooth)
                    .AddCrease(0, 2, 0.5).AddCrease(2, 3, 1.8).AddCrease(3, 1, 0.5).AddCrease(1, 0, 1.8);
                SubdivisionOptions chaikin = uniform.Clone();
                chaikin.Creasing = Creasing.Chaikin;
                using (var u = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, uniform))
                using (var c = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, chaikin))
                {
                    double[] pu = u.GetPositions(), pc = c.GetPositions();
                    double largest = 0;
                    for (int i = 0; i < pu.Length; i++) largest = Math.Max(largest, Math.Abs(pu[i] - pc[i]));
                    t.True(largest > 1e-6, "Chaikin moves some vertex, by " + largest);
                }
            }
        }

        private static void LoopCorner()
        {
            var options = new SubdivisionOptions(NakedEdges.Smooth).AddCorner(4, SubdivisionOptions.SharpnessInfinite);
            using (var octa = Shapes.Octahedron())
            using (var refined = Subdivision.Subdivide(octa, Scheme.Loop, 2, options))
            using (var plain = Subdivision.Loop(octa, 2, NakedEdges.Smooth))
            {
                t.Equal(plain.VertexCount, refined.VertexCount, "vertex count");
                t.Sequence(new[] { 0.0, 0.0, 1.0 }, Shapes.Vertex(refined, 4), "apex kept");
                t.True(Shapes.Vertex(plain, 4)[2] < 0.9, "without the corner the apex moves in");
            }
        }

        private static void CountsMatch()
        {
            using (var cube = Shapes.Cube())
            using (var refined = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, Hard(BottomLoop)))
            {
                SubdivisionCounts c = Subdivision.Counts(cube, Scheme.CatmullClark, 2);
                t.Equal(refined.VertexCount, c.VertexCount, "vertices");
                t.Equal(refined.FaceCount, c.FaceCount, "faces");
                t.Equal(refined.IndexCount, c.IndexCount, "face corners");
                t.Equal(98, c.VertexCount, "98 vertices for the cube at level 2");
            }
            using (var octa = Shapes.Octahedron())
            using (var refined = Subdivision.Subdivide(octa, Scheme.Loop, 3, null))
            {
                SubdivisionCounts c = Subdivision.Counts(octa, Scheme.Loop, 3);
                t.Equal(refined.VertexCount, c.VertexCount, "Loop vertices");
                t.Equal(512, c.FaceCount, "Loop faces: 8 × 64");
                t.Equal(3 * 512, c.IndexCount, "Loop face corners");
            }
        }

        private static void VertexDataIsPositions()
        {
            var options = Hard(BottomLoop).AddCorner(7, 3.5);
            using (var cube = Shapes.Cube())
            using (var refined = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, options))
            {
                double[] carried = Subdivision.SubdivideVertexData(cube, Scheme.CatmullClark, 2, options, UnitCube.Positions, 3);
                Shapes.Near(refined.GetPositions(), carried, 1e-12, "carried positions");
                // A constant colour (width 4) stays that colour everywhere.
                var colours = new double[4 * 8];
                for (int v = 0; v < 8; v++)
                {
                    colours[4 * v] = 200; colours[4 * v + 1] = 100; colours[4 * v + 2] = 50; colours[4 * v + 3] = 255;
                }
                double[] refinedColours = Subdivision.SubdivideVertexData(cube, Scheme.CatmullClark, 2, options, colours, 4);
                t.Equal(4 * 98, refinedColours.Length, "4 values per refined vertex");
                var expected = new double[refinedColours.Length];
                for (int v = 0; v < 98; v++)
                {
                    expected[4 * v] = 200; expected[4 * v + 1] = 100; expected[4 * v + 2] = 50; expected[4 * v + 3] = 255;
                }
                Shapes.Near(expected, refinedColours, 1e-9, "constant colour");
                // Into a caller buffer, larger than needed: the rest is untouched.
                var buffer = new double[3 * 98 + 2];
                buffer[3 * 98] = -7;
                Subdivision.SubdivideVertexData(cube, Scheme.CatmullClark, 2, options, UnitCube.Positions, 3, buffer);
                t.Equal(carried[5], buffer[5], "caller buffer filled");
                t.Equal(-7.0, buffer[3 * 98], "past the end untouched");
            }
        }

        private static void FaceVaryingWithoutSeams()
        {
            var options = Hard(BottomLoop);
            using (var cube = Shapes.Cube())
            using (var refined = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, options))
            {
                // One value per vertex, used by all of its corners: no seams, smooth rules.
                double[] values = Subdivision.SubdivideFaceVarying(cube, Scheme.CatmullClark, 2, options, FaceVaryingLinear.Smooth,
                    UnitCube.Positions, 3, UnitCube.Indices);
                uint[] indices = refined.GetFaceIndices();
                t.Equal(3 * indices.Length, values.Length, "3 values per refined face corner");
                double[] positions = refined.GetPositions();
                var expected = new double[values.Length];
                for (int c = 0; c < indices.Length; c++)
                {
                    for (int k = 0; k < 3; k++) expected[3 * c + k] = positions[3 * indices[c] + k];
                }
                Shapes.Near(expected, values, 1e-12, "face-varying = vertex values at each corner");
            }
        }

        private static void LimitSurfaceAnywhere()
        {
            var options = new SubdivisionOptions(NakedEdges.Smooth);
            using (var cube = Shapes.Cube())
            using (var surface = new LimitSurfaceEvaluator(cube, Scheme.CatmullClark, options))
            {
                LimitSurface limit = Subdivision.SubdivideLimit(cube, Scheme.CatmullClark, 1, options);
                uint v = (uint)cube.GetFaceIndices()[0];
                var p = new double[6];
                var du = new double[6];
                surface.Evaluate(new uint[] { 0, 0 }, new[] { 0.0, 0.0, 0.5, 0.5 }, p, du, null);
                Shapes.Near(new[] { limit.Positions[3 * v], limit.Positions[3 * v + 1], limit.Positions[3 * v + 2] },
                            new[] { p[0], p[1], p[2] }, 1e-12, "corner 0 of face 0 is its vertex's limit");
                var faces = new uint[1];
                var uvs = new double[2];
                var found = new double[3];
                surface.ClosestPoints(new[] { 0.5, 0.5, 3.0 }, faces, uvs, found);
                var again = new double[3];
                surface.Evaluate(faces, uvs, again, null, null);
                t.Sequence(again, found, "the closest point is the surface at its face and (u, v)");
                var e = t.Throws<WeftException>(() => surface.Evaluate(new uint[] { 6 }, new[] { 0.5, 0.5 }, p, null, null), "a face out of range");
                t.Equal(WeftStatus.IndexOutOfRange, e.Status, "its status");
            }
        }

        private static void LimitSurface()
        {
            var options = new SubdivisionOptions(NakedEdges.Smooth).AddCorner(7, SubdivisionOptions.SharpnessInfinite);
            using (var cube = Shapes.Cube())
            {
                LimitSurface limit = Subdivision.SubdivideLimit(cube, Scheme.CatmullClark, 2, options);
                t.Equal(3 * 98, limit.Positions.Length, "3 doubles per refined vertex");
                t.Sequence(new[] { 1.0, 1.0, 1.0 }, new[] { limit.Positions[21], limit.Positions[22], limit.Positions[23] }, "the corner's limit is itself");
                int bad = 0;
                for (int v = 0; v < 98; v++)
                {
                    double nx = limit.Normals[3 * v], ny = limit.Normals[3 * v + 1], nz = limit.Normals[3 * v + 2];
                    double length = Math.Sqrt(nx * nx + ny * ny + nz * nz);
                    if (v == 7) continue; // at a sharp corner the normal may be undefined
                    double outward = nx * (limit.Positions[3 * v] - 0.5) + ny * (limit.Positions[3 * v + 1] - 0.5) + nz * (limit.Positions[3 * v + 2] - 0.5);
                    if (Math.Abs(length - 1) > 1e-9 || outward <= 0) bad++;
                }
                t.Equal(0, bad, "vertices whose normal is not unit and outward");
                // The limit of a level differs from the level's vertices (they lie inside the limit surface).
                using (var refined = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, options))
                {
                    double[] p = refined.GetPositions();
                    t.True(Math.Abs(p[0] - limit.Positions[0]) > 1e-6, "vertex 0 moved onto the limit");
                }
                // Normals optional, into caller buffers.
                var positions = new double[3 * 98];
                Subdivision.SubdivideLimit(cube, Scheme.CatmullClark, 2, options, positions, null);
                t.Sequence(limit.Positions, positions, "positions without normals");
            }
        }

        private static void RefinerWithOptions()
        {
            var options = Hard(BottomLoop).AddCorner(7, 2);
            var moved = (double[])UnitCube.Positions.Clone();
            for (int i = 0; i < moved.Length; i++) moved[i] *= 3;
            moved[3 * 5 + 2] += 0.5;
            using (var cube = Shapes.Cube())
            using (var refiner = new Refiner(cube, Scheme.CatmullClark, 2, options))
            using (var movedCube = WeftMesh.Create(moved, UnitCube.Sizes, UnitCube.Indices))
            using (var fresh = Subdivision.Subdivide(movedCube, Scheme.CatmullClark, 2, options))
            using (var plain = Subdivision.CatmullClark(movedCube, 2, NakedEdges.Smooth))
            {
                var output = new double[3 * refiner.VertexCount];
                refiner.Evaluate(moved, output);
                Shapes.Near(fresh.GetPositions(), output, 1e-12, "re-evaluated creased positions");
                t.True(Math.Abs(plain.GetPositions()[2] - output[2]) > 1e-6, "the creases matter");
                using (var mesh = refiner.Mesh())
                using (var original = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, options))
                {
                    Shapes.Near(original.GetPositions(), mesh.GetPositions(), 1e-12, "refiner mesh");
                }
                // The options were copied: changing them does not change the plan.
                options.Clear();
                refiner.Evaluate(moved, output);
                Shapes.Near(fresh.GetPositions(), output, 1e-12, "after the options changed");
            }
            using (var cube = Shapes.Cube())
            {
                var bad = new SubdivisionOptions().AddCrease(0, 7, 10);
                Shapes.Fails(() => new Refiner(cube, Scheme.CatmullClark, 1, bad), WeftStatus.InvalidArgument,
                    "crease 0 joins vertices 0 and 7, which are not an edge of the mesh");
            }
        }

        /// <summary>The cube's six faces, each with its own four vertices (24 in all).</summary>
        private static WeftMesh UnweldedCube()
        {
            var positions = new double[3 * 24];
            var indices = new uint[24];
            for (int c = 0; c < 24; c++)
            {
                uint v = UnitCube.Indices[c];
                Array.Copy(UnitCube.Positions, 3 * (int)v, positions, 3 * c, 3);
                indices[c] = (uint)c;
            }
            return WeftMesh.Create(positions, UnitCube.Sizes, indices);
        }

        private static void CreaseEdgesFromUnweldedCube()
        {
            using (var pieces = UnweldedCube())
            {
                uint[] pairs;
                using (var welded = Subdivision.CreaseEdgesFromMesh(pieces, 180, out pairs))
                {
                    t.Equal(8, welded.VertexCount, "welded vertices");
                    t.True(welded.Info().IsClosed, "welded is closed");
                    t.Equal(24, pairs.Length, "12 creases, two vertices each");
                    using (var refined = Subdivision.Subdivide(welded, Scheme.CatmullClark, 3, Hard(pairs)))
                    {
                        // Every vertex stays on the cube's surface: some coordinate is 0 or 1.
                        double[] p = refined.GetPositions();
                        int off = 0;
                        for (int v = 0; v < p.Length / 3; v++)
                        {
                            bool onFace = false;
                            for (int k = 0; k < 3; k++)
                            {
                                double x = p[3 * v + k];
                                if (Math.Abs(x) < 1e-12 || Math.Abs(x - 1) < 1e-12) onFace = true;
                            }
                            if (!onFace) off++;
                        }
                        t.Equal(0, off, "vertices off the cube's surface");
                    }
                }
            }
        }

        private static void CreaseEdgesByAngle()
        {
            using (var cube = Shapes.Cube())
            {
                uint[] pairs;
                using (var welded = Subdivision.CreaseEdgesFromMesh(cube, 45, out pairs))
                {
                    t.Equal(24, pairs.Length, "every 90° fold is sharper than 45°");
                    t.Equal(8, welded.VertexCount, "nothing to weld");
                }
                using (var welded = Subdivision.CreaseEdgesFromMesh(cube, 100, out pairs))
                {
                    t.Equal(0, pairs.Length, "no fold sharper than 100°");
                }
                Shapes.Fails(() => Subdivision.CreaseEdgesFromMesh(cube, -1, out pairs), WeftStatus.InvalidArgument,
                    "the crease angle is -1 degrees; it must be 0 or more");
                Shapes.Fails(() => Subdivision.CreaseEdgesFromMesh(cube, double.NaN, out pairs), WeftStatus.InvalidArgument, "NaN");
            }
        }

        private static void CreaseEdgesVertexMap()
        {
            using (var pieces = UnweldedCube())
            {
                uint[] pairs, plainPairs, map;
                using (var welded = Subdivision.CreaseEdgesFromMesh(pieces, 180, out pairs, out map))
                using (var plain = Subdivision.CreaseEdgesFromMesh(pieces, 180, out plainPairs))
                {
                    t.Equal(24, map.Length, "one entry per input vertex");
                    t.Sequence(plainPairs, pairs, "the same creases as without the map");
                    t.Sequence(plain.GetPositions(), welded.GetPositions(), "the same weld as without the map");
                    double[] input = pieces.GetPositions(), output = welded.GetPositions();
                    // A value per input vertex from its position (a colour, say) follows the map onto the welded mesh.
                    var carried = new double[welded.VertexCount];
                    var seen = new bool[welded.VertexCount];
                    int misplaced = 0, next = 0, outOfOrder = 0;
                    for (int v = 0; v < map.Length; v++)
                    {
                        int w = (int)map[v];
                        t.True(w >= 0 && w < welded.VertexCount, "map[" + v + "] is a welded vertex");
                        if (w < 0 || w >= welded.VertexCount) return;
                        for (int k = 0; k < 3; k++)
                        {
                            if (output[3 * w + k] != input[3 * v + k]) misplaced++;
                        }
                        // Welded vertices are numbered in the order their position first appears.
                        if (!seen[w])
                        {
                            if (w != next) outOfOrder++;
                            next++;
                            seen[w] = true;
                        }
                        carried[w] = input[3 * v] + 2 * input[3 * v + 1] + 4 * input[3 * v + 2];
                    }
                    t.Equal(0, misplaced, "coordinates of input vertices away from their welded vertex");
                    t.Equal(0, outOfOrder, "welded vertices numbered out of first-use order");
                    t.Equal(8, next, "every welded vertex is some input vertex's");
                    for (int v = 0; v < map.Length; v++)
                    {
                        t.Equal(input[3 * v] + 2 * input[3 * v + 1] + 4 * input[3 * v + 2], carried[map[v]], "value carried to vertex " + v);
                    }
                }
            }
            using (var cube = Shapes.Cube())
            {
                uint[] pairs, map;
                using (var welded = Subdivision.CreaseEdgesFromMesh(cube, 45, out pairs, out map))
                {
                    t.Sequence(new uint[] { 0, 1, 2, 3, 4, 5, 6, 7 }, map, "a welded mesh maps to itself");
                    t.Equal(24, pairs.Length, "12 folds");
                }
                Shapes.Fails(() => Subdivision.CreaseEdgesFromMesh(cube, double.NaN, out pairs, out map), WeftStatus.InvalidArgument, "NaN");
                t.Throws<ArgumentNullException>(() => Subdivision.CreaseEdgesFromMesh(null, 30, out pairs, out map), "null mesh");
            }
            var disposed = Shapes.Cube();
            disposed.Dispose();
            uint[] none, noMap;
            t.Throws<ObjectDisposedException>(() => Subdivision.CreaseEdgesFromMesh(disposed, 30, out none, out noMap), "disposed mesh");
        }

        private static void OptionsValue()
        {
            var a = new SubdivisionOptions(NakedEdges.CornerFixed).AddCrease(0, 1, 2).AddCorner(3, 4);
            t.Equal(1, a.CreaseCount, "crease count");
            t.Equal(1, a.CornerCount, "corner count");
            t.Sequence(new uint[] { 0, 1 }, a.GetCreaseVertexPairs(), "pairs");
            t.Sequence(new[] { 4.0 }, a.GetCornerSharpness(), "corner sharpness");
            SubdivisionOptions b = a.Clone();
            t.True(a.SameAs(b), "a clone is the same");
            b.AddCrease(1, 3, 2);
            t.False(a.SameAs(b), "a changed clone differs");
            t.Equal(1, a.CreaseCount, "the original unchanged");
            SubdivisionOptions c = a.Clone();
            c.Creasing = Creasing.Chaikin;
            t.False(a.SameAs(c), "the rule counts");
            t.Equal(NakedEdges.Fixed, new SubdivisionOptions().NakedEdges, "the default naked edges are the C default");
            Shapes.Fails(() => a.AddCreases(new uint[] { 1, 2, 3 }, 1), WeftStatus.CountMismatch, "vertexPairs holds 3 indices, which is not 2 per crease");
            Shapes.Fails(() => a.AddCorner(-2, 1), WeftStatus.InvalidArgument, "vertex is -2");
        }

        private static void CreaseErrors()
        {
            using (var cube = Shapes.Cube())
            {
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, new SubdivisionOptions().AddCrease(0, 7, 10)),
                    WeftStatus.InvalidArgument, "crease 0 joins vertices 0 and 7, which are not an edge of the mesh");
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, new SubdivisionOptions().AddCrease(0, 1, 1).AddCrease(6, 1, 1)),
                    WeftStatus.InvalidArgument, "crease 1 joins vertices 6 and 1");
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, new SubdivisionOptions().AddCrease(0, 1, -1)),
                    WeftStatus.InvalidArgument, "crease 0 (0, 1) has sharpness -1");
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, new SubdivisionOptions().AddCrease(0, 1, double.NaN)),
                    WeftStatus.InvalidArgument, "sharpness NaN");
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, new SubdivisionOptions().AddCorner(8, 10)),
                    WeftStatus.InvalidArgument, "corner 0 is vertex 8, but the mesh has 8 vertices");
                var unknownRule = new SubdivisionOptions { Creasing = (Creasing)7 };
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, unknownRule), WeftStatus.InvalidArgument, "creasing is 7");
                var unknownNaked = new SubdivisionOptions((NakedEdges)9);
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, unknownNaked), WeftStatus.InvalidArgument, "naked_edges is 9");
                Shapes.Fails(() => Subdivision.Subdivide(cube, (Scheme)5, 1, null), WeftStatus.InvalidArgument, "scheme is 5");
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.Loop, 1, null), WeftStatus.NotTriangles, "face 0 has 4 vertices");
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, -1, null), WeftStatus.InvalidArgument, "levels is -1");
                Shapes.Fails(() => Subdivision.Counts(cube, (Scheme)5, 1), WeftStatus.InvalidArgument, "scheme is 5");
            }
        }

        private static void DataErrors()
        {
            using (var cube = Shapes.Cube())
            {
                var seven = new double[21];
                Shapes.Fails(() => Subdivision.SubdivideVertexData(cube, Scheme.CatmullClark, 1, null, seven, 3), WeftStatus.CountMismatch, "");
                Shapes.Fails(() => Subdivision.SubdivideVertexData(cube, Scheme.CatmullClark, 1, null, UnitCube.Positions, 0), WeftStatus.InvalidArgument, "width");
                Shapes.Fails(() => Subdivision.SubdivideVertexData(cube, Scheme.CatmullClark, 1, null, UnitCube.Positions, -3), WeftStatus.InvalidArgument, "width is -3");
                Shapes.Fails(() => Subdivision.SubdivideVertexData(cube, Scheme.CatmullClark, 1, null, UnitCube.Positions, 3, new double[3 * 26 - 1]),
                    WeftStatus.BufferTooSmall, "out_data has room for 77 elements but 78 are needed");
                Shapes.Fails(() => Subdivision.SubdivideLimit(cube, Scheme.CatmullClark, 1, null, new double[3 * 26 - 1], new double[3 * 26 - 1]),
                    WeftStatus.BufferTooSmall, "77");
                Shapes.Fails(() => Subdivision.SubdivideLimit(cube, Scheme.CatmullClark, 1, null, new double[3 * 26], new double[3]),
                    WeftStatus.CountMismatch, "normals holds 3 doubles but positions holds 78");
                var bad = (uint[])UnitCube.Indices.Clone();
                bad[5] = 8;
                Shapes.Fails(() => Subdivision.SubdivideFaceVarying(cube, Scheme.CatmullClark, 1, null, FaceVaryingLinear.All, UnitCube.Positions, 3, bad),
                    WeftStatus.IndexOutOfRange, "face corner 5 uses value 8");
                var short23 = new uint[23];
                Shapes.Fails(() => Subdivision.SubdivideFaceVarying(cube, Scheme.CatmullClark, 1, null, FaceVaryingLinear.All, UnitCube.Positions, 3, short23),
                    WeftStatus.CountMismatch, "");
                Shapes.Fails(() => Subdivision.SubdivideFaceVarying(cube, Scheme.CatmullClark, 1, null, (FaceVaryingLinear)6, UnitCube.Positions, 3, UnitCube.Indices),
                    WeftStatus.InvalidArgument, "face_varying_linear is 6");
                Shapes.Fails(() => Subdivision.SubdivideFaceVarying(cube, Scheme.CatmullClark, 1, null, FaceVaryingLinear.All, new double[10], 3, UnitCube.Indices),
                    WeftStatus.CountMismatch, "values holds 10 doubles, which is not 3 per value");
                Shapes.Fails(() => Subdivision.SubdivideFaceVarying(cube, Scheme.CatmullClark, 1, null, FaceVaryingLinear.All, UnitCube.Positions, 3, UnitCube.Indices, new double[10]),
                    WeftStatus.BufferTooSmall, "");
            }
            // Catmull-Clark's limit at level 0 needs quads.
            using (var mixed = WeftMesh.Create(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, new uint[] { 3 }, new uint[] { 0, 1, 2 }))
            {
                Shapes.Fails(() => Subdivision.SubdivideLimit(mixed, Scheme.CatmullClark, 0, null), WeftStatus.InvalidArgument, "");
            }
        }

        private static void DisposedMesh()
        {
            var cube = Shapes.Cube();
            cube.Dispose();
            uint[] pairs;
            t.Throws<ObjectDisposedException>(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, null), "subdivide");
            t.Throws<ObjectDisposedException>(() => Subdivision.Counts(cube, Scheme.CatmullClark, 1), "counts");
            t.Throws<ObjectDisposedException>(() => Subdivision.SubdivideVertexData(cube, Scheme.CatmullClark, 1, null, UnitCube.Positions, 3), "vertex data");
            t.Throws<ObjectDisposedException>(() => Subdivision.SubdivideLimit(cube, Scheme.CatmullClark, 1, null), "limit");
            t.Throws<ObjectDisposedException>(() => Subdivision.CreaseEdgesFromMesh(cube, 30, out pairs), "crease edges");
            t.Throws<ObjectDisposedException>(() => new Refiner(cube, Scheme.CatmullClark, 1, new SubdivisionOptions()), "refiner");
            t.Throws<ArgumentNullException>(() => Subdivision.Subdivide(null, Scheme.CatmullClark, 1, null), "null mesh");
            using (var live = Shapes.Cube())
            {
                t.Throws<ArgumentNullException>(() => Subdivision.SubdivideVertexData(live, Scheme.CatmullClark, 1, null, null, 3), "null data");
            }
        }

        private static void Holes()
        {
            using (var cube = Shapes.Cube())
            {
                SubdivisionOptions options = new SubdivisionOptions(NakedEdges.Smooth).AddHole(1).AddHole(4);
                t.Equal(2, options.HoleCount, "hole count");
                t.False(options.SameAs(new SubdivisionOptions(NakedEdges.Smooth)), "holes make options differ");
                t.True(options.Clone().SameAs(options), "a clone keeps the holes");
                using (var holed = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, options))
                using (var plain = Subdivision.Subdivide(cube, Scheme.CatmullClark, 2, new SubdivisionOptions(NakedEdges.Smooth)))
                {
                    t.Equal(plain.VertexCount, holed.VertexCount, "every vertex stays");
                    t.Equal(96 - 32, holed.FaceCount, "two faces' 16 children each are gone");
                    SubdivisionCounts counts = Subdivision.Counts(cube, Scheme.CatmullClark, 2, options);
                    t.Equal(holed.FaceCount, counts.FaceCount, "counts with options: faces");
                    t.Equal(4 * holed.FaceCount, counts.IndexCount, "counts with options: indices");
                    uint[] parents = Subdivision.ParentFaces(cube, Scheme.CatmullClark, 2, options);
                    t.Equal(holed.FaceCount, parents.Length, "a parent per face");
                    t.True(Array.TrueForAll(parents, p => p != 1 && p != 4), "no face comes from a hole");
                    var uvs = new double[2 * 24];
                    var indices = new uint[24];
                    for (int i = 0; i < 24; i++) indices[i] = (uint)i;
                    double[] corners = Subdivision.SubdivideFaceVarying(cube, Scheme.CatmullClark, 2, options, FaceVaryingLinear.All, uvs, 2, indices);
                    t.Equal(2 * counts.IndexCount, corners.Length, "face-varying values for the kept corners only");
                }
                Shapes.Fails(() => Subdivision.Subdivide(cube, Scheme.CatmullClark, 1, new SubdivisionOptions().AddHole(6)),
                    WeftStatus.InvalidArgument, "hole 0 is face 6, but the mesh has 6 faces");
            }
        }

        private static void NoneAndTriangles()
        {
            using (var grid = Shapes.Grid(0.5))
            using (var none = Subdivision.CatmullClark(grid, 1, NakedEdges.None))
            {
                t.Equal(0, none.FaceCount, "every face of a 2 x 2 grid touches the boundary: all holes");
                t.Equal(9 + 12 + 4, none.VertexCount, "the points stay");
            }
            using (var prism = Shapes.Cube())
            {
                var smooth = new SubdivisionOptions(NakedEdges.Smooth) { Triangles = TriangleRule.Smooth };
                t.True(new SubdivisionOptions(NakedEdges.Smooth) { Triangles = TriangleRule.Smooth }.SameAs(smooth), "same rule, same options");
                t.False(new SubdivisionOptions(NakedEdges.Smooth).SameAs(smooth), "the triangle rule counts");
                using (var quads = Subdivision.Subdivide(prism, Scheme.CatmullClark, 1, smooth))
                using (var catmark = Subdivision.Subdivide(prism, Scheme.CatmullClark, 1, new SubdivisionOptions(NakedEdges.Smooth)))
                {
                    Shapes.Near(catmark.GetPositions(), quads.GetPositions(), 0.0, "without triangles the rule changes nothing");
                }
                var unknown = new SubdivisionOptions(NakedEdges.Smooth) { Triangles = (TriangleRule)5 };
                Shapes.Fails(() => Subdivision.Subdivide(prism, Scheme.CatmullClark, 1, unknown), WeftStatus.InvalidArgument, "triangles is 5");
            }
        }
    }
}
