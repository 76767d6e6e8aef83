"""Edit logs replayed: what `edgeland replay` does with a landscape's log (el_replay_*)."""
import ctypes
from typing import NamedTuple, Optional

from . import _native, results
from ._handles import Owned, made
from .errors import EdgelandError, LoadError, failure
from .landscape import Landscape

_lib = _native.lib


class Replay(NamedTuple):
    """A replayed edit log: the landscape (recording its own log from the start, so it can be
    edited and shared again; None when the log has no good world line), the edits applied,
    why it stopped before the log's end (None, or the LoadError of a line that cannot be read or
    an edit refused, `index` its line, 1-based; an InternalError for a bug of edgeland's) and
    the JSON text `edgeland replay` prints for the log."""
    landscape: Optional[Landscape]
    edits: int
    stopped: Optional[EdgelandError]
    report: str


def replay_log(text):
    """Replays a landscape edit log (Landscape.log's text, str or bytes) as `edgeland replay`
    does: the world of its world line, then its edits in order up to the first bad line or
    refused edit, those before it kept. The text is untrusted: a bad log is a Replay that
    stopped, not an exception. Close the Replay's landscape (or use it in a with block) to free
    it at once."""
    data = text.encode() if isinstance(text, str) else bytes(text)
    with Owned(made(_lib.el_replay_log, data, len(data)), "el_replay_destroy") as replay:
        stopped = failure(_lib.el_replay_stopped, replay)
        with Owned(made(_lib.el_replay_report, replay), "el_bytes_destroy") as report:
            report_text = results.read_bytes(report).decode()
        out = ctypes.c_void_p()
        no_world = failure(_lib.el_replay_landscape, replay, ctypes.byref(out))
        if no_world is not None and not isinstance(no_world, LoadError):
            raise no_world
        landscape = None if no_world is not None else Landscape(_pointer=out.value)
        return Replay(landscape, _lib.el_replay_edits(replay), stopped, report_text)
