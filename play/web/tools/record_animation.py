#!/usr/bin/env python3
"""Records the README's physics animation from the browser playground (play/web/README.md).

Headless Chromium runs a short scene through window.playground (bodies rain on the demo world,
explosions open the ground under them, a tunnel is dug, a crater is flooded), the canvas is
captured every few frames, and ImageMagick's `convert` (Debian `imagemagick`) joins the frames
into an animated GIF. Usage:
  record_animation.py --web-dir build/web --out play/pictures/physics.gif
"""
import argparse
import base64
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', 'test'))
import browser_test  # noqa: E402  (the server and the browser of the test)

# (frame, JavaScript run before it) in world units of the 4096 x 2048 demo world.
SCENE = [
    (0, 'for (let k = 0; k < 28; ++k) { const x = 120 + k * 140;'
        ' if (k % 2) p.dropBall(x, 1950); else p.dropBox(x, 1950); }'),
    (70, 'p.explode(1200, 1330, 170); p.explode(2100, 1330, 200);'),
    (95, 'p.explode(3000, 1320, 190); p.explode(1650, 1200, 150);'),
    (120, 'for (let k = 0; k < 8; ++k) p.dig(500 + 90 * k, 1150 - 25 * k, 590 + 90 * k,'
          ' 1125 - 25 * k, 60);'),
    (150, 'p.water(2100, 1190, 150);'),
    (170, 'p.fill(9, 3000, 1230, 80);'),
]
FRAMES = 240
EVERY = 4

CAPTURE = """
const p = window.playground, [script, frames] = [arguments[0], arguments[1]];
if (script) new Function('p', script)(p);
p.runFrames(frames);
return document.getElementById('view').toDataURL('image/png');
"""


def record(args):
    server = browser_test.serve(args.web_dir)
    driver = browser_test.browser()
    try:
        driver.get(f'http://127.0.0.1:{server.server_port}/index.html')
        driver.execute_async_script('playground.ready.then(() => arguments[0]())')
        scene = dict(SCENE)
        with tempfile.TemporaryDirectory() as work:
            for frame in range(0, FRAMES, EVERY):
                script = ' '.join(scene.get(f, '') for f in range(frame, frame + EVERY))
                png = driver.execute_script(CAPTURE, script, EVERY)
                with open(os.path.join(work, f'frame_{frame:05d}.png'), 'wb') as f:
                    f.write(base64.b64decode(png.split(',', 1)[1]))
            frames = sorted(os.path.join(work, n) for n in os.listdir(work))
            subprocess.run(['convert', '-delay', '6', '-loop', '0', *frames, '-resize', '640x320',
                            '-layers', 'Optimize', args.out], check=True)
    finally:
        driver.quit()
        server.shutdown()
    print(f'{args.out}: {FRAMES // EVERY} frames, {os.path.getsize(args.out)} bytes')


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--web-dir', required=True)
    parser.add_argument('--out', required=True)
    record(parser.parse_args())


if __name__ == '__main__':
    main()
