#!/usr/bin/python3
"""The multi-process scenarios of issue 37 (net/README.md, store/README.md), each bounded in time,
on loopback addresses only, stopping every process it starts by its own pid:

  load        N `edgeland client --headless` processes against `edgeland serve`, each editing in
              its own box at R edits a second for S seconds: every client's hash equals the
              server's at every checkpoint; prints bytes per edit, latency p50/p99, server CPU.
  rejoin      a client killed with SIGKILL and started again rejoins to the server's hash.
  hostile     a hostile client (garbage, oversized, out-of-range, invalid, outside its box,
              flood) gets its typed rejections or a disconnect; the honest clients lose nothing.
  crash       `edgeland stream` writing to SQLite is killed with SIGKILL between the start and the
              end of a commit, again and again: every region reported committed is there, the
              database is sound, the world loads; resumed, the run ends at the in-memory hash.
  two-servers two `edgeland serve` processes own the two halves of one world on one PostgreSQL
              store (a real server started here, as the postgres user when run as root); the
              same edits, across the line between them too, go to both; the world combined from
              the stored regions has the single-process run's hash. Then the store's ownership
              rules (postgres_store_tests).

Exit status 0 when the scenario holds, 1 when it does not; one JSON line of figures at the end.
"""
import argparse
import json
import os
import pwd
import queue
import random
import shutil
import signal
import sqlite3
import subprocess
import sys
import tempfile
import threading
import time

STARTED = []  # every process this script started, stopped by pid at the end


class Proc:
    """A process with its stdout read line by line in a thread (no read ever blocks the script)."""

    def __init__(self, args, name):
        self.name = name
        self.p = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                  bufsize=1)
        STARTED.append(self)
        self.lines = queue.Queue()
        self.out = []
        self.err = []
        threading.Thread(target=self._read, args=(self.p.stdout, self.out, True), daemon=True).start()
        threading.Thread(target=self._read, args=(self.p.stderr, self.err, False), daemon=True).start()

    def _read(self, stream, keep, queued):
        for line in stream:
            keep.append(line)
            if queued:
                self.lines.put(line)
        if queued:
            self.lines.put(None)

    def line(self, timeout):
        """The next stdout line, or None at its end or after `timeout` seconds."""
        try:
            return self.lines.get(timeout=timeout)
        except queue.Empty:
            return None

    def wait(self, timeout):
        try:
            return self.p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.p.kill()
            self.p.wait()
            return None

    def kill9(self):
        os.kill(self.p.pid, signal.SIGKILL)
        self.p.wait()

    def json(self):
        """The last JSON line it printed (its summary)."""
        time.sleep(0.05)  # the reader thread may be a line behind the exit
        for line in reversed(self.out):
            if line.startswith("{"):
                return json.loads(line)
        return None


def stop_all():
    for proc in STARTED:
        if proc.p.poll() is None:
            proc.p.kill()
            proc.p.wait()


def fail(why, **figures):
    print(json.dumps({"ok": False, "why": why, **figures}))
    for proc in STARTED:
        if proc.err:
            sys.stderr.write(f"--- {proc.name} stderr ---\n" + "".join(proc.err[-20:]))
    return 1


def serve(edgeland, name, *args):
    server = Proc([edgeland, "serve", "--until-idle", *args], name)
    first = server.line(60)
    if not first:
        raise RuntimeError(f"{name} did not start: " + "".join(server.err))
    return server, json.loads(first)["port"]


def client(edgeland, name, port, *args):
    return Proc([edgeland, "client", "--headless", "--server", f"127.0.0.1:{port}", *args], name)


def percentile(values, p):
    values = sorted(values)
    return values[min(len(values) - 1, len(values) * p // 100)] if values else None


def in_step(summary, server_hash=None):
    return (summary is not None and summary["welcomed"] and summary["in_step"]
            and summary["mismatched"] == 0 and summary["matched"] == summary["checkpoints"]
            and summary["checkpoints"] > 0
            and (server_hash is None or summary.get("state_hash") == server_hash))


# --- load ------------------------------------------------------------------------------------
def load(a):
    side = 8192
    grid = 4  # 16 boxes of 2048 x 2048
    server, port = serve(a.edgeland, "server", "--seconds", str(a.seconds + 120),
                         "--edits-per-second", str(2 * a.rate), "--burst", str(4 * a.rate),
                         "--world-size", str(side))
    clients = []
    for k in range(a.clients):
        x, y = (k % grid) * side // grid, (k // grid % grid) * side // grid
        clients.append(client(a.edgeland, f"client{k}", port, "--edit-box", str(x + 10), str(y + 10),
                              str(x + side // grid - 10), str(y + side // grid - 10),
                              "--edits-per-second", str(a.rate), "--seconds", str(a.seconds),
                              "--linger", "30", "--seed", str(k + 1), "--print-latencies"))
    codes = [c.wait(a.seconds + 90) for c in clients]
    if server.wait(60) is None:
        return fail("the server did not stop by itself")
    s = server.json()
    summaries = [c.json() for c in clients]
    # Every checkpoint matched (each client stops when its own edits are back, while others may
    # still be editing: its last hash is the server's at its last checkpoint, not at the end).
    bad = [k for k, (code, c) in enumerate(zip(codes, summaries))
           if code != 0 or not in_step(c) or c["edits_applied"] != c["edits_sent"]]
    latencies = [us for c in summaries if c for us in c.get("latencies_us", [])]
    edits = s["edits"]
    figures = {
        "clients": a.clients, "seconds": a.seconds, "rate": a.rate, "edits": edits,
        "checkpoints_per_client": min(c["checkpoints"] for c in summaries if c) if all(summaries) else 0,
        "command_bytes_per_edit": round(s["command_bytes"] / max(1, s["commands_sent"]), 1),
        "server_bytes_sent_per_edit": round(s["bytes_sent"] / max(1, edits), 1),
        "server_bytes_sent_per_edit_per_client": round(s["bytes_sent"] / max(1, edits) / a.clients, 1),
        "latency_p50_ms": round(percentile(latencies, 50) / 1000, 2) if latencies else None,
        "latency_p99_ms": round(percentile(latencies, 99) / 1000, 2) if latencies else None,
        "server_cpu_seconds": round(s["cpu_seconds"], 3),
        "server_cpu_share": round(s["cpu_seconds"] / s["wall_seconds"], 4),
        "rejects": s["rejects"],
    }
    expected = a.clients * a.rate * a.seconds
    if bad:
        return fail(f"clients {bad} were not in step with the server or lost edits", **figures)
    if edits < expected * 9 // 10 or s["rejects"]:
        return fail(f"{edits} edits applied of about {expected}, or rejections", **figures)
    print(json.dumps({"ok": True, **figures}))
    return 0


# --- rejoin ----------------------------------------------------------------------------------
def rejoin(a):
    server, port = serve(a.edgeland, "server", "--seconds", str(a.seconds + 120))
    args = lambda k: ["--edit-box", str(100 + 2000 * k), "100", str(1900 + 2000 * k), "1900",
                      "--edits-per-second", "10", "--seconds", str(a.seconds), "--linger", "30",
                      "--seed", str(k + 1)]
    clients = [client(a.edgeland, f"client{k}", port, *args(k)) for k in range(3)]
    time.sleep(a.seconds / 3)
    clients[0].kill9()
    # Started again at once: a new client, which joins from the snapshot and the log after it
    # (its old box is still granted to the dead client until the server times it out: it may
    # edit nothing, it must still mirror the world). It outlasts the others, so its last hash is
    # the server's last.
    again = client(a.edgeland, "restarted", port, *args(0)[:-6], "--seconds", str(a.seconds),
                   "--linger", "30")
    codes = [c.wait(a.seconds + 90) for c in clients[1:] + [again]]
    if server.wait(90) is None:
        return fail("the server did not stop by itself")
    s = server.json()
    summaries = [c.json() for c in clients[1:] + [again]]
    figures = {"edits": s["edits"], "joins": s["joins"], "restarted": summaries[-1]}
    if any(code != 0 for code in codes) or not all(in_step(c) for c in summaries):
        return fail("a client, or the restarted one, missed a checkpoint", **figures)
    if summaries[-1]["state_hash"] != s["state_hash"]:
        return fail("the restarted client did not end at the server's hash", **figures)
    print(json.dumps({"ok": True, "edits": s["edits"], "joins": s["joins"],
                      "restarted_checkpoints": summaries[-1]["checkpoints"]}))
    return 0


# --- hostile ---------------------------------------------------------------------------------
def hostile(a):
    server, port = serve(a.edgeland, "server", "--seconds", str(a.seconds + 120))
    honest = [client(a.edgeland, f"honest{k}", port, "--edit-box", str(100 + 2000 * k), "100",
                     str(1900 + 2000 * k), "1900", "--edits-per-second", "10", "--seconds",
                     str(a.seconds), "--linger", "30", "--seed", str(k + 1)) for k in range(3)]
    time.sleep(1)
    bad = client(a.edgeland, "hostile", port, "--edit-box", "100", "4100", "1900", "5900",
                 "--hostile", "all", "--seconds", "10")
    bad_code = bad.wait(60)
    codes = [c.wait(a.seconds + 90) for c in honest]
    if server.wait(90) is None:
        return fail("the server did not stop by itself")
    s, h = server.json(), bad.json()
    summaries = [c.json() for c in honest]
    figures = {"hostile": h, "server_rejects": s["rejects"], "dropped": s["dropped"]}
    if bad_code != 0 or h is None:
        return fail("an attack got neither its typed rejection nor a disconnect", **figures)
    if any(code != 0 for code in codes) or not all(
            in_step(c, s["state_hash"]) and c["edits_applied"] == c["edits_sent"] for c in summaries):
        return fail("an honest client lost an edit or left the server's state", **figures)
    print(json.dumps({"ok": True, **figures}))
    return 0


# --- crash -----------------------------------------------------------------------------------
def crash(a):
    work = tempfile.mkdtemp(prefix="edgeland_crash_")
    db = os.path.join(work, "regions.db")
    sweep = ["--world-size", "8192", "--region-depth", "4"]
    writer_args = [a.edgeland, "stream", "--store", f"sqlite:{db}", "--budget", "400000",
                   "--trace-commits", *sweep]
    rng = random.Random(37)
    committed = {}  # path -> the sequence number it was reported committed at
    kills = 0
    try:
        for round_ in range(a.rounds):
            writer = Proc(writer_args, f"writer{round_}")
            target, begun, killed = rng.randint(2, 12), 0, False
            while True:
                line = writer.line(120)
                if line is None:
                    break
                words = line.split()
                if words[0] == "commit-begin":
                    begun += 1
                    if begun == target:  # between the start and the end of a commit
                        writer.kill9()
                        kills += 1
                        killed = True
                        break
                elif words[0] == "commit-end":
                    for entry in words[2:]:
                        seq, path = entry.split(":")
                        committed[path] = max(committed.get(path, 0), int(seq))
            if not killed:
                writer.wait(60)
            problem = check_store(a.edgeland, db, committed)
            if problem:
                return fail(f"after kill {kills}: {problem}", kills=kills)
        # The last run goes to the end of the sweep; it must end at the in-memory run's hash.
        final = Proc(writer_args[:-len(sweep) - 1] + sweep, "final")
        if final.wait(600) != 0:
            return fail("the resumed run failed", kills=kills)
        memory = Proc([a.edgeland, "stream", *sweep], "memory")
        if memory.wait(600) != 0:
            return fail("the in-memory run failed")
        streamed, in_memory = final.json(), memory.json()
        problem = check_store(a.edgeland, db, committed)
        if problem or streamed["state_hash"] != in_memory["state_hash"]:
            return fail(problem or "the resumed run did not end at the in-memory hash",
                        streamed=streamed, memory=in_memory)
        print(json.dumps({"ok": True, "kills": kills, "regions_reported_committed": len(committed),
                          "state_hash": streamed["state_hash"], "vertices": streamed["vertices"]}))
        return 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


def check_store(edgeland, db, committed):
    """None when every region reported committed is there at its sequence number or later, the
    database is sound and the world loads; else what is wrong."""
    with sqlite3.connect(db) as c:
        if c.execute("PRAGMA integrity_check").fetchone()[0] != "ok":
            return "the database failed its integrity check"
        rows = {bytes(p).hex(): seq for p, seq in c.execute("SELECT path, seq FROM regions")}
    for path, seq in committed.items():
        key = bytes(int(d) for d in path).hex()
        if rows.get(key, -1) < seq:
            return f"region {path} committed at {seq} is at {rows.get(key)}"
    loaded = Proc([edgeland, "store", f"sqlite:{db}"], "store")
    if loaded.wait(300) != 0:
        return "the world does not load: " + "".join(loaded.out + loaded.err)
    return None


# --- two servers -----------------------------------------------------------------------------
class Postgres:
    """A PostgreSQL 15 server in a temporary directory, Unix socket only (TOOLCHAIN.md 19)."""

    BIN = "/usr/lib/postgresql/15/bin"

    def __init__(self):
        self.dir = tempfile.mkdtemp(prefix="edgeland_pg_")
        self.port = "5433"
        as_root = os.geteuid() == 0
        if as_root:
            pg = pwd.getpwnam("postgres")
            os.chown(self.dir, pg.pw_uid, pg.pw_gid)
        self.prefix = ["runuser", "-u", "postgres", "--"] if as_root else []
        data = os.path.join(self.dir, "data")
        self.run([f"{self.BIN}/initdb", "-D", data, "-A", "trust", "-U", "postgres"])
        self.run([f"{self.BIN}/pg_ctl", "-D", data, "-w", "-t", "60", "-o",
                  f"-k {self.dir} -p {self.port} -c listen_addresses=''", "-l",
                  os.path.join(self.dir, "log"), "start"])
        self.data = data
        self.conninfo = f"host={self.dir} port={self.port} user=postgres dbname=postgres"

    def run(self, args):
        subprocess.run(self.prefix + args, check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, timeout=120)

    def stop(self):
        subprocess.run(self.prefix + [f"{self.BIN}/pg_ctl", "-D", self.data, "-m", "fast", "stop"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120)
        shutil.rmtree(self.dir, ignore_errors=True)


def two_servers(a):
    pg = Postgres()
    try:
        store = f"postgres:{pg.conninfo}"
        # Region depth 3: indices 0-15 and 32-47 lie left of x = 4096, the others right of it.
        left = ",".join(str(i) for i in list(range(0, 16)) + list(range(32, 48)))
        right = ",".join(str(i) for i in list(range(16, 32)) + list(range(48, 64)))
        common = ["--store", store, "--world-size", "8192", "--region-depth", "3",
                  "--edits-per-second", "200", "--burst", "400", "--commit-ms", "300",
                  "--seconds", str(a.seconds + 120)]
        first, port_a = serve(a.edgeland, "server A", *common, "--server-name", "A", "--own", left)
        second, port_b = serve(a.edgeland, "server B", *common, "--server-name", "B", "--own", right)
        # A strip either side of x = 4096, the line between the two owners: many edits cross it.
        box = ["3840", "0", "4352", "8192"]
        edit = ["--edit-box", *box, "--edits-per-second", str(a.rate),
                "--seconds", str(a.seconds), "--linger", "30", "--seed", "7"]
        clients = [client(a.edgeland, "client A", port_a, "--watch", left, *edit),
                   client(a.edgeland, "client B", port_b, "--watch", right, *edit)]
        codes = [c.wait(a.seconds + 90) for c in clients]
        if first.wait(60) is None or second.wait(60) is None:
            return fail("a server did not stop by itself")
        summaries = [c.json() for c in clients]
        if any(code != 0 for code in codes) or not all(in_step(c) for c in summaries):
            return fail("a client did not end in step with its server", clients=summaries)
        sent = summaries[0]["edits_sent"]
        if summaries[1]["edits_sent"] != sent or any(c["edits_applied"] != sent for c in summaries):
            return fail("the two servers did not apply the same edits", clients=summaries)
        combined = Proc([a.edgeland, "store", store, "--world-size", "8192", "--region-depth", "3",
                         "--replay-seed", "7", "--replay-count", str(sent), "--replay-box", *box],
                        "combined")
        code, result = combined.wait(300), combined.json()
        if code != 0:
            return fail("the world combined from the two servers' regions is not the single "
                        "process's", result=result)
        pg.run([f"{Postgres.BIN}/createdb", "-h", pg.dir, "-p", pg.port, "-U", "postgres", "rules"])
        rules = subprocess.run([a.store_tests], capture_output=True, text=True, timeout=300,
                               env={**os.environ, "EDGELAND_TEST_POSTGRES":
                                    pg.conninfo.replace("dbname=postgres", "dbname=rules")})
        if rules.returncode != 0:
            sys.stderr.write(rules.stdout[-4000:])
            return fail("the store's ownership rules failed (postgres_store_tests)")
        if result["replayed_edits_across_region_lines"] == 0:
            return fail("no edit crossed a region line", result=result)
        print(json.dumps({"ok": True, "edits": sent,
                          "edits_across_region_lines": result["replayed_edits_across_region_lines"],
                          "state_hash": result["state_hash"], "replayed_hash": result["replayed_hash"],
                          "regions": result["regions"]}))
        return 0
    finally:
        stop_all()
        pg.stop()


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenario", choices=["load", "rejoin", "hostile", "crash", "two-servers"])
    parser.add_argument("--edgeland", required=True, help="the edgeland command")
    parser.add_argument("--store-tests", dest="store_tests", help="postgres_store_tests (two-servers)")
    parser.add_argument("--clients", type=int, default=16)
    parser.add_argument("--seconds", type=int, default=10)
    parser.add_argument("--rate", type=int, default=10)
    parser.add_argument("--rounds", type=int, default=5)
    a = parser.parse_args()
    run = {"load": load, "rejoin": rejoin, "hostile": hostile, "crash": crash,
           "two-servers": two_servers}[a.scenario]
    try:
        return run(a)
    finally:
        stop_all()


if __name__ == "__main__":
    sys.exit(main())
