// The C# binding under Mono: its checks (no argument), or the mirror script against the C++
// run's hashes (tests/mirror/README.md; argument: the hash file). Prints "csharp: N checks
// passed" / "mirror_csharp: 5000 frames" and exits 0, or names the failed check and exits 1.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Edgeland;

static class Tests
{
    static int checks;

    static void Check(bool ok, string what)
    {
        ++checks;
        if (!ok) { Console.Error.WriteLine("check failed: " + what); Environment.Exit(1); }
    }

    static T Throws<T>(Action action, string what) where T : EdgelandException
    {
        try { action(); }
        catch (T e) { ++checks; return e; }
        catch (Exception e) { Check(false, what + ": threw " + e.GetType().Name); }
        Check(false, what + ": did not throw");
        return null;
    }

    static Point[] Square(long x, long y, long side)
    {
        return new[] { new Point(x, y), new Point(x + side, y), new Point(x + side, y + side), new Point(x, y + side) };
    }

    static void EditsAndChangeSets()
    {
        using (var world = new Landscape(new Box(0, 0, 1024, 512), 1))
        using (var hole = Shape.Circle(new Point(512, 256), 100))
        {
            var before = world.TwiceArea(1);
            ChangeSet changes = world.Carve(hole);
            Check(changes.Removed.Length > 0 && changes.Added.Length > 0 && changes.Cells.Length > 0, "a carve's change set");
            Check(changes.AreaDelta.Values.Aggregate((a, b) => a + b).IsZero, "area deltas sum to zero");
            Check(world.TwiceArea(1) == before + changes.AreaDelta[1], "twice area follows the delta");
            Check(world.MaterialAt(new Point(512, 256)) == 0, "carved out");
            var ids = new HashSet<ulong>(world.PolygonsIn(world.World).Select(p => p.Id));
            Check(changes.Added.All(p => ids.Contains(p.Id)) && !changes.Removed.Any(ids.Contains), "ids");
        }
    }

    static void ErrorsKeepTheWorld()
    {
        using (var world = new Landscape(new Box(0, 0, 1024, 512), 1))
        {
            ulong before = world.StateHash;
            var bad = Throws<InvalidInputException>(() => new Shape(new[] { new Point(0, 0), new Point(10, 10), new Point(10, 0), new Point(0, 10) }), "bow tie");
            Check(bad.Kind == 3 && bad.Index == 0, "the rule and polygon of the bow tie");
            var far = Throws<CoordinateOutOfRangeException>(() => new Shape(new[] { new Point(0, 0), new Point(3000000000, 0), new Point(0, 10) }), "far");
            Check(far.Vertex == 1 && far.Where.X == 3000000000, "the far vertex");
            using (var s = new Shape(Square(10, 10, 20)))
            {
                var m = Throws<InvalidMaterialException>(() => world.Fill(s, 300), "material 300");
                Check(m.Value == 300, "the material number");
            }
            Throws<ArgumentRangeException>(() => Shape.Circle(new Point(0, 0), 0), "radius 0");
            Throws<InvalidConfigException>(() => new Landscape(new Box(10, 0, 0, 10)), "inverted world");
            Throws<CoordinateOutOfRangeException>(() => world.MaterialAt(new Point(0, -3000000000)), "query out of range");
            Check(world.StateHash == before, "refused edits leave the world");
        }
    }

    static void Queries()
    {
        using (var world = new Landscape(new Box(0, 0, 1024, 512), 1))
        using (var pit = new Shape(Square(100, 100, 50)))
        using (var ore = new Shape(Square(300, 100, 20)))
        {
            world.Carve(pit);
            world.Fill(ore, 3);
            Crossing? hit = world.Raycast(new Point(120, 125), new Point(120, 400));
            Check(hit.HasValue && hit.Value.Rounded.Y == 150 && hit.Value.After == 1, "raycast");
            Check(hit.Value.YNum.ToBigInteger() == 150 * hit.Value.Den.ToBigInteger(), "exact hit point");
            Check(world.Crossings(new Point(120, 125), new Point(120, 400)).Length == 1, "crossings");
            Check(world.Overlaps(new Box(0, 0, 400, 200)).SequenceEqual(new byte[] { 1, 3 }), "overlaps");
            Check(world.Overlaps(pit).Length == 0, "overlaps of a shape");
        }
    }

    static void SnapshotsAndSaves()
    {
        using (var world = new Landscape(new Box(0, 0, 1024, 512), 1))
        using (var box = Shape.Rectangle(new Box(100, 100, 150, 150)))
        {
            using (var snapshot = world.Clone())
            {
                world.Carve(box);
                Check(snapshot.StateHash != world.StateHash && snapshot.MaterialAt(new Point(120, 120)) == 1, "snapshot");
            }
            byte[] data = world.Save();
            using (var loaded = Landscape.Load(data)) Check(loaded.StateHash == world.StateHash, "save -> load");
            data[data.Length / 2] ^= 0x40;
            Throws<LoadException>(() => Landscape.Load(data), "a broken save");
            Check(world.Check().Length == 0, "check()");
        }
    }

    static void GameLayer()
    {
        using (var world = new Landscape(new Box(0, 0, 1024, 512)))
        using (var surface = new SurfaceTracker(world))
        using (var islands = new IslandTracker(world))
        using (var ground = new Shape(Square(0, 0, 100)))
        using (var floating = new Shape(Square(400, 300, 40)))
        {
            ChangeSet changes = world.Fill(ground, 1);
            ChainUpdate update = surface.Update(world, changes);
            Check(update.Added.Length >= 1 && update.Added[0].Materials[0] == 1 && update.Added[0].Info.Closed == 0, "ground chains");
            using (Islands none = islands.Update(world, changes)) Check(none.All.Length == 0, "the ground is held");
            changes = world.Fill(floating, 2);
            Chain[] added = surface.Update(world, changes).Added;
            Check(added.Length == 1 && added[0].Info.Closed == 1, "a closed chain around the floating square");
            ulong[] dropped;
            Check(Game.MeshUpdate(changes, out dropped)[0].Triangles.Length == 6, "a square's mesh");
            using (Islands found = islands.Update(world, changes))
            {
                Check(found.All.Length == 1 && found.All[0].TwiceArea == 3200 && found.All[0].Pieces[0].Material == 2, "the island");
                using (Detached d = Game.Detach(world, found, 0))
                {
                    Check(d.TwiceArea == 3200 && d.CentroidXNum == 420 * d.CentroidDen && d.Regions.Length == 1, "detached");
                    Check(world.MaterialAt(new Point(420, 320)) == 0, "the island is gone");
                    Check(surface.Update(world, d.Changes).Removed.SequenceEqual(new[] { added[0].Info.Id }), "its chain removed");
                    using (Islands again = islands.Update(world, d.Changes)) Check(again.All.Length == 0, "no island left");
                }
                Throws<StaleIslandException>(() => Game.Detach(world, found, 0), "a stale island");
                Throws<IndexRangeException>(() => Game.Detach(world, found, 1), "an island index out of range");
            }
            Check(Game.AllMeshes(world).Length == world.PolygonsIn(world.World).Length, "all meshes");
            var ell = new[] { new Point(0, 0), new Point(20, 0), new Point(20, 10), new Point(10, 10), new Point(10, 20), new Point(0, 20) };
            Check(Game.ConvexPieces(ell).Length == 2, "convex pieces");
            Throws<InvalidArgumentException>(() => Game.ConvexPieces(ell, 2), "max vertices 2");
        }
    }

    // An empty world of 8 x 8 cells, so the ground's surface crosses cell lines.
    static Landscape CellWorld(ulong maxShapeVertices = 1 << 20)
    {
        LandscapeConfig c = Landscape.DefaultConfig();
        c.GridDepth = 3;
        c.Flags = 1;
        c.MaxShapeVertices = maxShapeVertices;
        return new Landscape(new Box(0, 0, 1024, 512), 0, c);
    }

    // The chains a game holds, kept from the updates alone.
    static void Follow(Dictionary<ulong, Chain> mirror, ChainUpdate update)
    {
        foreach (ulong id in update.Removed) Check(mirror.Remove(id), "an update removed chain " + id + ", which the game holds");
        foreach (Chain c in update.Added) mirror.Add(c.Info.Id, c);
    }

    static bool Holds(Dictionary<ulong, Chain> mirror, GameDriver game)
    {
        Chain[] all = game.Chains;
        return all.Length == mirror.Count && all.All(c => mirror.ContainsKey(c.Info.Id) &&
            mirror[c.Info.Id].Info.Equals(c.Info) && mirror[c.Info.Id].Points.SequenceEqual(c.Points));
    }

    static void GameDriverFrames()
    {
        using (var world = CellWorld())
        using (var game = new GameDriver(world))
        using (var ground = Shape.Rectangle(new Box(0, 0, 1024, 100)))
        using (var rock = Shape.Rectangle(new Box(400, 300, 440, 340)))
        using (var pillar = Shape.Rectangle(new Box(600, 60, 650, 250)))
        using (var crater = Shape.Circle(new Point(300, 100), 60))
        {
            var mirror = new Dictionary<ulong, Chain>();
            using (GameUpdate u = game.Apply(Edit.Fill(ground, 1), Edit.Fill(rock, 2)))
            {
                Follow(mirror, u.Chains);
                Check(u.Debris.Length == 1, "the rock fell");
                Debris d = u.Debris[0];
                Check(d.TwiceArea == 3200 && d.CentroidXNum == 420 * d.CentroidDen && d.CentroidYNum == 320 * d.CentroidDen, "its area and centroid");
                Check(d.Regions.Length == 1 && d.Pieces.Length == 1 && d.Pieces[0].Material == 2 && d.Pieces[0].Points.Length == 4, "its region and piece");
                Check(d.Meshes.Length == 1 && d.Meshes[0].Triangles.Length == 6, "its mesh");
                Check(u.MeshesBuilt.Select(m => m.Id).OrderBy(i => i).SequenceEqual(u.Changes.Added.Select(p => p.Id).OrderBy(i => i)), "a mesh per new polygon");
                Check(u.Work.IslandsDetached == 1 && u.Work.CellsScanned >= 1, "the work");
            }
            Check(Holds(mirror, game), "the mirror holds the driver's chains");
            int joints = 0;
            Chain[] open = game.Chains.Where(c => c.Info.Closed == 0).ToArray();
            foreach (Chain a in open)
                foreach (Chain b in open)
                    if (a != b && a.Points[a.Points.Length - 1].Equals(b.Points[0]))
                    {
                        Check(a.Info.GhostNext.Equals(b.Points[1]) && b.Info.GhostPrev.Equals(a.Points[a.Points.Length - 2]), "ghosts across a cell line");
                        ++joints;
                    }
            Check(joints == 7, "the ground's top crosses 7 cell lines");
            using (Landscape now = game.Landscape) Check(now.MaterialAt(new Point(420, 320)) == 0 && world.MaterialAt(new Point(10, 10)) == 0, "the driver's world and the caller's");

            using (GameUpdate u = game.Apply(Edit.Fill(pillar, 3))) Follow(mirror, u.Chains);
            Check(game.Buried(new Box(610, 210, 620, 220)) && !game.Buried(new Box(100, 400, 110, 410)), "buried bodies");

            using (Landscape before = game.Landscape)
            {
                using (GameUpdate u = game.Apply(Edit.Carve(crater))) Follow(mirror, u.Chains);
                using (Landscape after = game.Landscape) Check(after.StateHash != before.StateHash && Holds(mirror, game), "a carve");
                using (GameUpdate u = game.Reset(before)) Follow(mirror, u.Chains);
                using (Landscape now = game.Landscape) Check(now.StateHash == before.StateHash && Holds(mirror, game), "reset to the snapshot");
            }
        }
    }

    static void GameDriverErrors()
    {
        using (var world = CellWorld(16))
        using (var small = Shape.Rectangle(new Box(10, 10, 50, 50)))
        using (var round = Shape.Circle(new Point(500, 300), 100))
        {
            var e = Throws<InvalidArgumentException>(() => new GameDriver(world, new GameOptions { MaxPieceVertices = 2 }), "pieces of 2 vertices");
            Check(e.Value == 2 && e.Minimum == 3, "the argument's value and minimum");
            using (var game = new GameDriver(world))
            {
                ulong hash;
                using (Landscape now = game.Landscape) hash = now.StateHash;
                int chains = game.Chains.Length;
                Check(Throws<InvalidMaterialException>(() => game.Apply(Edit.Carve(small), Edit.Fill(small, 300)), "material 300").Value == 300, "its value");
                var limit = Throws<LimitExceededException>(() => game.Apply(Edit.Carve(small), Edit.Fill(round, 1)), "a shape past the limit");
                Check(limit.Limit == 16, "the limit");
                using (Landscape now = game.Landscape) Check(now.StateHash == hash && game.Chains.Length == chains, "the driver as it was");
            }
            var options = new GameOptions { MaxPieceVertices = 3, Meshes = false };
            using (var game = new GameDriver(world, options))
            using (var rock = Shape.Rectangle(new Box(400, 300, 440, 340)))
            using (GameUpdate u = game.Apply(Edit.Fill(rock, 4)))
                Check(u.Debris.Length == 1 && u.Debris[0].Pieces.Length == 2 && u.Debris[0].Meshes.Length == 0 && u.MeshesBuilt.Length == 0, "triangles, no meshes");
        }
    }

    // Twice the signed area of a ring (shoelace): positive when counter-clockwise.
    static long TwiceArea(Point[] ring)
    {
        long sum = 0;
        for (int i = 0; i < ring.Length; ++i)
        {
            Point a = ring[i], b = ring[(i + 1) % ring.Length];
            sum += a.X * b.Y - b.X * a.Y;
        }
        return sum;
    }

    static long TwiceArea(Point[][] polygons) { return polygons.Sum(p => TwiceArea(p)); }

    static Point[] Ring(params long[] xy)
    {
        var ring = new Point[xy.Length / 2];
        for (int i = 0; i < ring.Length; ++i) ring[i] = new Point(xy[2 * i], xy[2 * i + 1]);
        return ring;
    }

    // An import's pieces are a valid set: counter-clockwise, and new Shape (which checks every
    // rule) takes them as they are.
    static void CheckValid(Shape s, string what)
    {
        Point[][] polygons = s.Polygons;
        Check(polygons.All(p => TwiceArea(p) > 0), what + ": counter-clockwise pieces");
        using (var again = new Shape(polygons))
            Check(again.Polygons.Length == polygons.Length, what + ": a valid set");
    }

    // Shape.Import (el_shape_import): rings as others draw them, read with OGC semantics.
    static void ShapeImport()
    {
        Point[] bowTie = Ring(0, 0, 100, 100, 100, 0, 0, 100);
        Throws<InvalidInputException>(() => new Shape(bowTie), "a bow tie as drawn");
        using (var s = Shape.Import(new[] { new[] { bowTie } }))
        using (var world = new Landscape(new Box(0, 0, 256, 256)))
        {
            CheckValid(s, "bow tie");
            // OGC: the two triangles meeting where the edges cross.
            long ogc = Math.Abs(TwiceArea(Ring(0, 0, 50, 50, 0, 100))) + Math.Abs(TwiceArea(Ring(50, 50, 100, 100, 100, 0)));
            Check(s.Polygons.Length == 2 && TwiceArea(s.Polygons) == ogc, "the bow tie's two lobes");
            world.Fill(s, 2);
            Check(world.TwiceArea(2) == ogc && world.MaterialAt(new Point(10, 50)) == 2 && world.MaterialAt(new Point(50, 10)) == 0, "the bow tie filled");
        }
        Point[] clockwise = Ring(0, 0, 0, 10, 10, 10, 10, 0);
        Check(Throws<InvalidInputException>(() => new Shape(clockwise), "a clockwise ring as drawn").Kind == 5, "not counter-clockwise");
        using (var s = Shape.Import(new[] { new[] { clockwise } }))
        {
            CheckValid(s, "clockwise");
            Point[][] p = s.Polygons;
            Check(p.Length == 1 && TwiceArea(p[0]) == -TwiceArea(clockwise) && p[0].OrderBy(q => q.X).ThenBy(q => q.Y).SequenceEqual(clockwise.OrderBy(q => q.X).ThenBy(q => q.Y)), "the clockwise ring turned");
        }
        Point[] outer = Square(0, 0, 30), hole = Square(10, 10, 10);
        foreach (Point[] drawn in new[] { hole, hole.Reverse().ToArray() })
        {
            using (var s = Shape.Import(new[] { new[] { outer, drawn } }))
            using (var world = new Landscape(new Box(0, 0, 64, 64)))
            {
                CheckValid(s, "holed square");
                Check(s.Polygons.Length >= 2 && TwiceArea(s.Polygons) == 2 * (900 - 100), "the holed square's pieces");
                world.Fill(s, 2);
                Check(world.TwiceArea(2) == 2 * (900 - 100) && world.MaterialAt(new Point(15, 15)) == 0 && world.MaterialAt(new Point(5, 5)) == 2, "the holed square filled");
                Check(world.Check().Length == 0, "the holed square's world is valid");
            }
        }
        using (var s = Shape.Import(new[] { new[] { Square(0, 0, 10) }, new[] { Square(5, 5, 10) } }))
            Check(TwiceArea(s.Polygons) == 2 * (100 + 100 - 25), "two overlapping polygons: their union");
        using (var s = Shape.Import(new[] { new[] { Ring(0, 0, 10, 0, 20, 0) } }))
            Check(s.Polygons.Length == 0, "a ring of no area");
        var far = Throws<CoordinateOutOfRangeException>(() => Shape.Import(new[] { new[] { Square(0, 0, 5) }, new[] { Ring(0, 0, 1L << 40, 0, 0, 10) } }), "a vertex out of range");
        Check(far.Operand == 2 && far.Index == 1 && far.Vertex == 1 && far.Where.X == 1L << 40, "its polygon and vertex");
    }

    static long Area(Box b) { return (b.Max.X - b.Min.X) * (b.Max.Y - b.Min.Y); }
    static bool Meet(Box a, Box b) { return a.Min.X <= b.Max.X && b.Min.X <= a.Max.X && a.Min.Y <= b.Max.Y && b.Min.Y <= a.Max.Y; }
    static bool InteriorsMeet(Box a, Box b) { return a.Min.X < b.Max.X && b.Min.X < a.Max.X && a.Min.Y < b.Max.Y && b.Min.Y < a.Max.Y; }

    // CellsIn (el_landscape_cells_in): the cells tile the world, empty ones too.
    static void CellsTileTheWorld()
    {
        var all = new Box(0, 0, 1024, 512);
        using (var world = new Landscape(all, 1))
        {
            for (int k = 0; k < 12; ++k)  // enough edges to split the root
                using (var hole = Shape.Circle(new Point(40 + 80 * k, 100 + 25 * k), 30)) world.Carve(hole);
            Box[] cells = world.CellsIn();
            Check(cells.Length == (int)world.Stats.Cells && cells.Length > 1, "a cell per leaf");
            Check(cells.All(c => c.Min.X >= 0 && c.Max.X <= 1024 && c.Min.Y >= 0 && c.Max.Y <= 512 && Area(c) > 0), "cells inside the world");
            Check(cells.Sum(c => Area(c)) == Area(all), "the cells' area is the world's");
            bool overlap = false;
            for (int i = 0; i < cells.Length; ++i)
                for (int j = i + 1; j < cells.Length; ++j) overlap |= InteriorsMeet(cells[i], cells[j]);
            Check(!overlap, "cells' interiors are disjoint");
            Check(world.PolygonsIn(all).All(p => cells.Contains(p.Cell)), "every polygon's cell is a cell");
            foreach (Box b in new[] { new Box(0, 0, 10, 10), new Box(500, 200, 700, 300), new Box(512, 0, 512, 512) })
                Check(world.CellsIn(b).SequenceEqual(cells.Where(c => Meet(c, b))), "the cells a box meets, in tree order");
            Check(world.CellsIn(new Box(10, 0, 0, 10)).Length == 0, "an inverted box holds no point");
            Throws<CoordinateOutOfRangeException>(() => world.CellsIn(new Box(0, 0, 1L << 40, 10)), "a box out of range");
        }
        using (var empty = CellWorld())
        {
            Box[] cells = empty.CellsIn();
            Check(empty.PolygonsIn(empty.World).Length == 0 && cells.Length == 64 && cells.All(c => Area(c) == (1024 / 8) * (512 / 8)), "an empty world's 8 x 8 cells");
        }
    }

    // Landscape.ReplayLog (el_replay_*): a recorded log replays to the same world, a bad line
    // stops it there.
    static void ReplayLogs()
    {
        using (var world = new Landscape(new Box(0, 0, 1024, 512), 1))
        using (var blast = Shape.Circle(new Point(512, 256), 100))
        using (var ore = new Shape(Square(100, 100, 50)))
        using (var corner = new Shape(Square(0, 0, 200)))
        {
            world.StartLog();
            world.Carve(blast);
            using (Landscape first = world.Clone())
            {
                world.Fill(ore, 3);
                world.Relabel(corner, new KeyValuePair<int, int>(1, 4), new KeyValuePair<int, int>(3, 1));
                string log = world.Log;
                using (Replay r = Landscape.ReplayLog(log))
                {
                    Check(r.Stopped == null && r.Edits == 3, "a recorded log replays whole");
                    Check(r.Landscape.StateHash == world.StateHash && r.Landscape.Log == log, "to the same world, which records itself");
                    Check(r.Report.Contains("\"edits\":3,") && r.Report.Contains("\"state_hash\":\"" + world.StateHash.ToString("x16") + "\"") && !r.Report.Contains("stopped_at_line"), "the report");
                    Check(r.Report.Contains("\"polygons\":" + world.Stats.Polygons + ","), "the report's polygons");
                }
                string[] lines = log.Split(new[] { '\n' }, StringSplitOptions.RemoveEmptyEntries);
                foreach (string bad in new[] { "fill 300 POLYGON((0 0,10 0,10 10,0 10,0 0))", "smash 1 2 3", "carve POLYGON((0 0,10 0", "fill 1 POLYGON((0 0,3000000000 0,0 10,0 0))" })
                {
                    // After the world line and the first edit: that edit kept, the rest not.
                    var text = string.Join("\n", lines.Take(2).Concat(new[] { bad }).Concat(lines.Skip(2))) + "\n";
                    using (Replay r = Landscape.ReplayLog(text))
                    {
                        Check(r.Stopped is LoadException && r.Stopped.Index == 3 && r.Stopped.Message.StartsWith("line 3"), "stopped at line 3 by " + bad);
                        Check(r.Edits == 1 && r.Landscape.StateHash == first.StateHash && r.Report.Contains("\"stopped_at_line\":3"), "the edit before it kept");
                    }
                }
                using (Replay r = Landscape.ReplayLog(log + "fill 300 POLYGON((0 0,10 0,10 10,0 10,0 0))\n"))
                    Check(r.Stopped.Index == (ulong)lines.Length + 1 && r.Edits == 3 && r.Landscape.StateHash == world.StateHash, "a bad last line");
            }
        }
        foreach (string text in new[] { "carve POLYGON((0 0,1 0,1 1,0 1,0 0))\n", "world 10 0 0 10\n", "" })
            using (Replay r = Landscape.ReplayLog(text))
                Check(r.Landscape == null && r.Edits == 0 && r.Stopped is LoadException && r.Stopped.Index == 1 && r.Report.Contains("\"stopped_at_line\":1"), "no world: no landscape");
    }

    static void DisposedObjectsRefuseUse()
    {
        using (var world = new Landscape(new Box(0, 0, 100, 100), 1))
        {
            var s = Shape.Circle(new Point(10, 10), 5);
            s.Dispose();
            try { world.Carve(s); Check(false, "a disposed shape was used"); }
            catch (ObjectDisposedException) { ++checks; }
        }
    }

    // --- the mirror script (tests/mirror/README.md) ---
    static ulong state = 36;
    static ulong Next()
    {
        state += 0x9E3779B97F4A7C15UL;
        ulong z = state;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return z ^ (z >> 31);
    }
    static long Below(long n) { return (long)(Next() % (ulong)n); }

    static Shape DrawShape()
    {
        long kind = Below(3);
        var c = new Point(Below(2176) - 64, Below(1152) - 64);
        long r = 4 + Below(60);
        if (kind == 0) return Shape.Circle(c, r);
        if (kind == 1) { long h = 1 + r / 2; return Shape.Rectangle(new Box(c.X - r, c.Y - h, c.X + r, c.Y + h)); }
        long sides = 3 + Below(6);
        return Shape.RegularPolygon(c, r, sides, Below(16), 16);
    }

    static ChangeSet DrawEdit(Landscape world)
    {
        long op = Below(5);
        using (Shape s = DrawShape())
        {
            switch (op)
            {
                case 0: return world.Carve(s);
                case 1: return world.Fill(s, (int)(1 + Below(4)));
                case 2: return world.FillEmpty(s, (int)(1 + Below(4)));
                case 3: { int from = (int)Below(5); return world.Replace(s, from, (int)Below(5)); }
                default:
                    {
                        var pairs = new KeyValuePair<int, int>[2];
                        for (int i = 0; i < 2; ++i) { int from = (int)Below(5); pairs[i] = new KeyValuePair<int, int>(from, (int)Below(5)); }
                        return world.Relabel(s, pairs);
                    }
            }
        }
    }

    static SortedDictionary<ulong, Polygon> PolygonsOf(Landscape world)
    {
        var m = new SortedDictionary<ulong, Polygon>();
        foreach (Polygon p in world.PolygonsIn(world.World)) m[p.Id] = p;
        return m;
    }

    static bool Same(SortedDictionary<ulong, Polygon> a, SortedDictionary<ulong, Polygon> b)
    {
        return a.Count == b.Count && a.All(kv => b.ContainsKey(kv.Key) && b[kv.Key].Material == kv.Value.Material && b[kv.Key].Points.SequenceEqual(kv.Value.Points));
    }

    static void BadInput(Landscape world, int frame)
    {
        ulong before = world.StateHash;
        var bad = Throws<InvalidInputException>(() => new Shape(new[] { new Point(0, 0), new Point(10, 10), new Point(10, 0), new Point(0, 10) }), "bow tie at frame " + frame);
        Check(bad.Kind == 3, "self-intersection");
        using (var s = new Shape(Square(0, 0, 10)))
            Check(Throws<InvalidMaterialException>(() => world.Fill(s, 300), "material 300").Value == 300, "material number");
        Check(world.StateHash == before, "refused edits leave the world at frame " + frame);
    }

    static void Mirror(string hashes)
    {
        string[] expected = File.ReadAllLines(hashes);
        var world = new Landscape(new Box(0, 0, 2048, 1024), 1);
        Landscape snapshot = null;
        var mirror = PolygonsOf(world);
        SortedDictionary<ulong, Polygon> mirrorSnapshot = null;
        for (int f = 0; f < 5000; ++f)
        {
            if (f % 1000 == 500) BadInput(world, f);
            long edits = 1 + Below(3);
            for (long e = 0; e < edits; ++e)
            {
                ChangeSet c = DrawEdit(world);
                foreach (ulong id in c.Removed) mirror.Remove(id);
                foreach (Polygon p in c.Added) mirror[p.Id] = p;
            }
            if (f % 100 == 90)
            {
                if (snapshot != null) snapshot.Dispose();
                snapshot = world.Clone();
                mirrorSnapshot = new SortedDictionary<ulong, Polygon>(mirror);
            }
            if (f % 100 == 99)
            {
                world.Dispose();
                world = snapshot.Clone();
                mirror = new SortedDictionary<ulong, Polygon>(mirrorSnapshot);
            }
            if (f % 500 == 499)
            {
                byte[] bytes = world.Save();
                world.Dispose();
                world = Landscape.Load(bytes);
            }
            string[] line = expected[f].Split(' ');
            if (int.Parse(line[0]) != f || ulong.Parse(line[1]) != world.StateHash)
            {
                Console.Error.WriteLine("mirror_csharp: frame " + f + ": state hash differs from the C++ run's");
                Environment.Exit(1);
            }
            if (f % 100 == 99 || f == 4999) Check(Same(mirror, PolygonsOf(world)), "mirror at frame " + f);
        }
        world.Dispose();
        Console.WriteLine("mirror_csharp: 5000 frames");
    }

    static int Main(string[] args)
    {
        if (args.Length == 1) { Mirror(args[0]); return 0; }
        EditsAndChangeSets();
        ErrorsKeepTheWorld();
        Queries();
        SnapshotsAndSaves();
        GameLayer();
        GameDriverFrames();
        GameDriverErrors();
        ShapeImport();
        CellsTileTheWorld();
        ReplayLogs();
        DisposedObjectsRefuseUse();
        Console.WriteLine("csharp: " + checks + " checks passed");
        return 0;
    }
}
