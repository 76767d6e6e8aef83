"""replay_log (el_replay_*): edit logs replayed as `edgeland replay` does."""
import json

import pytest

import edgeland
from edgeland import Landscape, Shape


def square(x, y, side):
    return [[(x, y), (x + side, y), (x + side, y + side), (x, y + side)]]


@pytest.fixture
def recorded():
    """A world that recorded three edits, and a snapshot after the first."""
    world = Landscape(((0, 0), (1024, 512)), fill=1)
    world.start_log()
    world.carve(Shape.circle((512, 256), 100))
    first = world.copy()
    world.fill(square(100, 100, 50), 3)
    world.relabel(square(0, 0, 200), {1: 4, 3: 1})
    yield world, first
    world.close()
    first.close()


def lines(text):
    return text.splitlines(keepends=True)


def test_a_recorded_log_replays_to_the_same_world(recorded):
    world, _ = recorded
    replay = edgeland.replay_log(world.log)
    assert replay.stopped is None and replay.edits == 3
    with replay.landscape as replayed:
        assert replayed.state_hash == world.state_hash
        assert replayed.polygons_in() == world.polygons_in()
        assert replayed.log == world.log  # it records its own log from the start
    report = json.loads(replay.report)
    stats = world.stats
    assert report["edits"] == 3 and report["state_hash"] == "%016x" % world.state_hash
    assert (report["polygons"], report["cells"]) == (stats["polygons"], stats["cells"])
    assert "stopped_at_line" not in report


def test_a_replayed_world_can_be_edited_and_shared_again(recorded):
    world, _ = recorded
    with edgeland.replay_log(world.log.encode()).landscape as replayed:  # bytes work too
        replayed.carve(Shape.box((600, 0), (700, 100)))
        again = edgeland.replay_log(replayed.log)
        assert again.edits == 4 and again.landscape.state_hash == replayed.state_hash
        again.landscape.close()


def test_a_bad_line_stops_the_replay_there(recorded):
    world, first = recorded
    text = lines(world.log)
    for bad in ("fill 300 POLYGON((0 0,10 0,10 10,0 10,0 0))\n",  # no material 300
                "smash 1 2 3\n",                                   # an unknown command
                "carve POLYGON((0 0,10 0\n",                       # broken WKT
                "fill 1 POLYGON((0 0,3000000000 0,0 10,0 0))\n"):  # beyond the bound
        # After the world line and the first edit: the replay keeps that edit and stops.
        replay = edgeland.replay_log("".join(text[:2] + [bad] + text[2:]))
        assert isinstance(replay.stopped, edgeland.LoadError)
        assert replay.stopped.index == 3 and str(replay.stopped).startswith("line 3")
        assert replay.edits == 1
        assert replay.landscape.state_hash == first.state_hash
        assert json.loads(replay.report)["stopped_at_line"] == 3
        replay.landscape.close()
    # At the end: every edit before it kept.
    replay = edgeland.replay_log(world.log + "fill 300 POLYGON((0 0,10 0,10 10,0 10,0 0))\n")
    assert replay.stopped.index == len(text) + 1 and replay.edits == 3
    assert replay.landscape.state_hash == world.state_hash
    replay.landscape.close()


def test_a_log_without_a_world_has_no_landscape():
    for text in ("carve POLYGON((0 0,1 0,1 1,0 1,0 0))\n", "world 10 0 0 10\n", ""):
        replay = edgeland.replay_log(text)
        assert replay.landscape is None and replay.edits == 0
        assert isinstance(replay.stopped, edgeland.LoadError) and replay.stopped.index == 1
        report = json.loads(replay.report)
        assert report["edits"] == 0 and report["stopped_at_line"] == 1 and report["error"]
