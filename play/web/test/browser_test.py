#!/usr/bin/env python3
"""The browser playground in a real browser (play/web/README.md).

Headless Chromium (Debian's chromium, chromium-driver, python3-selenium) loads build/web (the page
over the JavaScript package) from a local http.server, runs a scripted edit sequence through
window.playground, and checks:
  * the page's state hash equals the native library's for the page's own edit log (`edgeland
    replay LOG`), and so do its polygon and vertex counts;
  * the demo world the page builds (the demo module's rings imported and applied through the
    package) is `edgeland demo`'s, bit for bit;
  * playground.replay(log) returns the object `edgeland replay LOG` prints (all keys but the
    timing);
  * undo and redo move between the states the edits made;
  * after frames of physics with bodies dropped, the canvas is not blank;
  * the console holds no errors.
It prints edits per second (the scripted edits, and the replays in the browser against the
native command of the page's log and of an `edgeland demo` log, whose state hash must match too)
and the frame time. Exit 0 when every check holds, 1 otherwise.
"""
import argparse
import functools
import gzip
import http.server
import json
import os
import random
import subprocess
import sys
import tempfile
import threading

from selenium import webdriver

WORLD = (0, 0, 4096, 2048)  # playground.js kWorld


def scripted_edits(count, seed):
    """A fixed sequence of tool edits over the ground of the demo world."""
    rng = random.Random(seed)
    x0, y0, x1, y1 = WORLD
    edits = []
    for _ in range(count):
        x, y = rng.randint(x0 + 64, x1 - 64), rng.randint(y0 + 64, y0 + (y1 - y0) * 3 // 4)
        r = rng.randint(12, 96)
        roll = rng.random()
        if roll < 0.5:
            edits.append(['explosion', x, y, x, y, r, 0, 0])
        elif roll < 0.75:
            dx, dy = rng.randint(-160, 160), rng.randint(-160, 160)
            edits.append(['digger', x, y, x + dx, y + dy, r // 2 + 6, 0, 0])
        elif roll < 0.85:
            edits.append(['fill', x, y, x, y, r, rng.choice([2, 3, 6, 9]), 0])
        elif roll < 0.93:
            edits.append(['water', x, y, x, y, r, 5, 0])
        else:
            edits.append(['replace', x, y, x, y, r, 4, 2])
    return edits


def serve(directory):
    handler = functools.partial(QuietHandler, directory=directory)
    server = http.server.ThreadingHTTPServer(('127.0.0.1', 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def browser():
    options = webdriver.ChromeOptions()
    for flag in ('--headless=new', '--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage',
                 '--window-size=1100,900'):
        options.add_argument(flag)
    options.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
    driver = webdriver.Chrome(options=options)
    driver.set_script_timeout(300)
    return driver


def demo_log(edgeland, edits, seed=1):
    """The log of `edgeland demo --edits N --seed S` (its 8192 x 8192 world)."""
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, 'demo.log')
        subprocess.run([edgeland, 'demo', '--edits', str(edits), '--seed', str(seed), '--unchecked',
                        '--out', work, '--log', path], capture_output=True, check=True)
        with open(path) as f:
            return f.read()


def native_replay(edgeland, log_text):
    with tempfile.NamedTemporaryFile('w', suffix='.log', delete=False) as f:
        f.write(log_text)
        path = f.name
    try:
        run = subprocess.run([edgeland, 'replay', path], capture_output=True, text=True, check=False)
    finally:
        os.unlink(path)
    if run.returncode != 0:
        raise RuntimeError(f'edgeland replay exited {run.returncode}: {run.stderr.strip()}')
    return json.loads(run.stdout.splitlines()[0])


RUN_EDITS = """
const [edits, done] = [arguments[0], arguments[arguments.length - 1]];
playground.ready.then(p => {
  const start = performance.now();
  let refused = 0;
  for (const e of edits) if (p.apply(...e).error) refused += 1;
  const ms = performance.now() - start;
  done({ms, refused, hash: p.stateHash(), stats: p.stats(), log: p.log()});
}).catch(e => done({failed: String(e)}));
"""

DEMO_WORLD = """
const [seed, done] = [arguments[0], arguments[arguments.length - 1]];
import('./world.mjs').then(({startingWorld}) => {
  const world = startingWorld([[0, 0], [8192, 8192]], 0, seed);
  done(world.stateHash.toString(16).padStart(16, '0'));
  world.dispose();
}).catch(e => done(String(e)));
"""

UNDO_REDO = """
const p = window.playground, before = p.stateHash();
p.undo(); const undone = p.stateHash();
p.undo(); p.redo(); const redone = p.stateHash();
p.redo(); return {before, undone, redone, after: p.stateHash()};
"""

PHYSICS_AND_PIXELS = """
const p = window.playground;
for (let k = 0; k < 24; ++k) {
  const x = 100 + k * 160;
  if (k % 2) p.dropBall(x, 1900, 24); else p.dropBox(x, 1900, 20);
}
const frames = p.runFrames(180);
const canvas = document.getElementById('view');
const pixels = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
const colours = new Set();
for (let k = 0; k < pixels.length; k += 4 * 97) colours.add(pixels[k] << 16 | pixels[k + 1] << 8 | pixels[k + 2]);
return {frames, colours: colours.size, bodies: p.stats().bodies};
"""


class Checks:
    def __init__(self):
        self.failed = 0
        self.passed = 0

    def expect(self, ok, what):
        print(('ok      ' if ok else 'FAILED  ') + what)
        if ok:
            self.passed += 1
        else:
            self.failed += 1


def compare_replays(checks, page_json, native_json):
    keys = sorted(set(page_json) | set(native_json) - {'edits_per_second'})
    differing = [k for k in keys
                 if k != 'edits_per_second' and page_json.get(k) != native_json.get(k)]
    checks.expect(not differing and 'edits_per_second' in page_json,
                  'playground.replay(log) returns what `edgeland replay` prints' +
                  (f' (differs in {differing})' if differing else ''))


def run(args):
    checks = Checks()
    server = serve(args.web_dir)
    driver = browser()
    try:
        driver.get(f'http://127.0.0.1:{server.server_port}/index.html')
        edits = scripted_edits(args.edits, args.seed)
        result = driver.execute_async_script(RUN_EDITS, edits)
        if 'failed' in result:
            raise RuntimeError('the page did not start: ' + result['failed'])
        native = native_replay(args.edgeland, result['log'])
        checks.expect(native['state_hash'] == result['hash'],
                      f"state hash after {len(edits)} scripted edits: page {result['hash']}, "
                      f"native replay of the page's log {native['state_hash']}")
        checks.expect(native['polygons'] == result['stats']['polygons'] and
                      native['vertices'] == result['stats']['vertices'],
                      'polygon and vertex counts equal the native replay\'s')
        checks.expect(result['refused'] == 0, f"no scripted edit refused ({result['refused']})")
        timing = driver.execute_script('return playground.timing')

        page_demo = driver.execute_async_script(DEMO_WORLD, 1)
        native_demo = native_replay(args.edgeland, demo_log(args.edgeland, 0, seed=1))['state_hash']
        checks.expect(page_demo == native_demo,
                      f"the demo world built through the package is `edgeland demo`'s "
                      f"(page {page_demo}, native {native_demo})")

        states = driver.execute_script(UNDO_REDO)
        checks.expect(states['undone'] != states['before'] and states['redone'] == states['undone']
                      and states['after'] == states['before'],
                      'undo and redo move between the edits\' states')

        page_replay = driver.execute_async_script(
            'const done = arguments[1]; playground.ready.then(p => done(p.replay(arguments[0])));',
            result['log'])
        compare_replays(checks, page_replay, native)

        shown = driver.execute_script(PHYSICS_AND_PIXELS)
        checks.expect(shown['colours'] >= 5, f"the canvas is not blank ({shown['colours']} colours)")
        checks.expect(shown['bodies'] > 0, f"bodies simulated ({shown['bodies']} left in the world)")
        if args.screenshot:
            driver.save_screenshot(args.screenshot)
            print(f'screenshot: {args.screenshot}')

        # Best of three each: the machine may be busy with other work.
        speed_log = demo_log(args.edgeland, args.speed_edits)
        native_speed = max((native_replay(args.edgeland, speed_log) for _ in range(3)),
                           key=lambda j: j['edits_per_second'])
        page_speed = max((driver.execute_async_script(
            'const done = arguments[1]; playground.ready.then(p => done(p.replay(arguments[0])));',
            speed_log) for _ in range(3)), key=lambda j: j['edits_per_second'])
        checks.expect(page_speed['state_hash'] == native_speed['state_hash'],
                      f"the demo log ({native_speed['edits']} edits) replays to the native state "
                      f"hash in the page ({page_speed['state_hash']})")
        errors = driver.execute_script('return playground.errors')
        console = [e for e in driver.get_log('browser') if e['level'] == 'SEVERE']
        checks.expect(not console and not errors,
                      f"no console errors {[e['message'] for e in console] + errors}")

        modules = {name: os.path.join(args.web_dir, *path) for name, path in
                   (('the package', ('edgeland', 'edgeland_c.mjs')), ('the demo module', ('demo.mjs',)))}
        page_rate = len(edits) / (result['ms'] / 1000)
        wasm_rate = len(edits) / (result['stats']['totalEditMs'] / 1000)
        print(f"scripted edits in the page: {len(edits)} in {result['ms']:.0f} ms, "
              f"{page_rate:.0f} edits/s with drawing and colliders, {wasm_rate:.0f} edits/s "
              f"in the package's calls alone (the game driver's edit and its update)")
        print(f"  of which the page's view {timing['viewMs']:.0f} ms, its planck.js colliders "
              f"{timing['collidersMs']:.0f} ms; {result['stats']['chains']} surface chains, "
              f"{result['stats']['islandsDetached']} islands detached")
        for name, page, ref in (("the page's log", page_replay, native),
                                (f'`edgeland demo --edits {args.speed_edits}` (best of 3)', page_speed,
                                 native_speed)):
            print(f"replay of {name} ({ref['edits']} edits): browser "
                  f"{page['edits_per_second']:.0f} edits/s, native "
                  f"{ref['edits_per_second']:.0f} edits/s, ratio browser/native "
                  f"{page['edits_per_second'] / ref['edits_per_second']:.2f}")
        frames = shown['frames']
        print(f"frames: {frames['frames']}, mean {frames['meanMs']:.2f} ms, max "
              f"{frames['maxMs']:.2f} ms (physics step and drawing, {shown['bodies']} bodies)")
        for name, path in modules.items():
            with open(path, 'rb') as f:
                data = f.read()
            print(f"{name}: {os.path.basename(path)} {len(data)} bytes (the wasm inlined), "
                  f"{len(gzip.compress(data, 9))} gzipped (-9)")
    finally:
        driver.quit()
        server.shutdown()
    print(f'{checks.passed} passed, {checks.failed} failed')
    return 0 if checks.failed == 0 else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--web-dir', required=True, help='the built page (scripts/build_web.sh)')
    parser.add_argument('--edgeland', required=True, help='the native `edgeland` command')
    parser.add_argument('--edits', type=int, default=300)
    parser.add_argument('--seed', type=int, default=29)
    parser.add_argument('--speed-edits', type=int, default=1000,
                        help='edits of the demo log replayed natively and in the page for speed')
    parser.add_argument('--screenshot', help='save a screenshot of the page here')
    sys.exit(run(parser.parse_args()))


if __name__ == '__main__':
    main()
