// Physics in the page from a real engine: planck.js (a JavaScript port of Box2D, pinned by
// play/web/package-lock.json). The terrain is one static body with a fixture per solid
// polygon of the landscape, a chain loop around it, rebuilt from the module's updates for the
// polygons that changed only. Balls and boxes are dynamic bodies. Engine units: metres, `unitsPerMetre` world
// units each, taken relative to the world box's corner (floats lose nothing there).
'use strict';

class Physics {
  constructor(box, unitsPerMetre, isSolid) {
    this.box = box;
    this.k = unitsPerMetre;
    this.isSolid = isSolid;
    this.world = new planck.World({gravity: planck.Vec2(0, -10)});
    this.ground = this.world.createBody();  // the static terrain: one fixture per polygon
    this.terrain = new Map();  // polygon id -> fixture
    this.dynamic = [];         // {body, kind: 'ball' | 'box', size (world units)}
  }

  metres(x, y) { return planck.Vec2((x - this.box.x0) / this.k, (y - this.box.y0) / this.k); }
  worldPoint(v) { return {x: this.box.x0 + v.x * this.k, y: this.box.y0 + v.y * this.k}; }

  // The terrain colliders of one update (removed ids, added polygons; a reset drops all).
  apply(update) {
    if (update.reset) {
      for (const fixture of this.terrain.values()) this.ground.destroyFixture(fixture);
      this.terrain.clear();
    }
    for (const id of update.removed) {
      const fixture = this.terrain.get(id);
      if (fixture) this.ground.destroyFixture(fixture);
      this.terrain.delete(id);
    }
    forEachAdded(update, (id, material, xy) => {
      if (!this.isSolid(material)) return;
      const points = [];
      for (let k = 0; k < xy.length; k += 2) points.push(this.metres(xy[k], xy[k + 1]));
      this.terrain.set(id, this.ground.createFixture(planck.Chain(points, true), {friction: 0.6}));
    });
  }

  dropBall(x, y, radius) {
    const body = this.world.createDynamicBody({position: this.metres(x, y)});
    body.createFixture(planck.Circle(radius / this.k), {density: 1, friction: 0.4, restitution: 0.2});
    this.dynamic.push({body, kind: 'ball', size: radius});
  }

  dropBox(x, y, half) {
    const body = this.world.createDynamicBody({position: this.metres(x, y), angle: 0.3});
    body.createFixture(planck.Box(half / this.k, half / this.k), {density: 1, friction: 0.5});
    this.dynamic.push({body, kind: 'box', size: half});
  }

  // One fixed step; bodies that fell out of the world are removed.
  step(seconds) {
    this.world.step(seconds, 8, 3);
    this.dynamic = this.dynamic.filter(d => {
      if (d.body.getPosition().y > -8) return true;  // 8 m below the world's floor: gone
      this.world.destroyBody(d.body);
      return false;
    });
  }

  // Every dynamic body's centre in world units (for tests and the overlay).
  centres() { return this.dynamic.map(d => this.worldPoint(d.body.getPosition())); }

  draw(context, view) {
    context.save();
    context.lineWidth = 1.5;
    for (const d of this.dynamic) {
      const c = this.worldPoint(d.body.getPosition());
      const x = view.px(c.x), y = view.py(c.y), s = d.size * view.scale;
      context.beginPath();
      if (d.kind === 'ball') {
        context.arc(x, y, s, 0, 2 * Math.PI);
      } else {
        const a = -d.body.getAngle(), cos = Math.cos(a) * s, sin = Math.sin(a) * s;
        context.moveTo(x + cos - sin, y + sin + cos);
        context.lineTo(x - cos - sin, y - sin + cos);
        context.lineTo(x - cos + sin, y - sin - cos);
        context.lineTo(x + cos + sin, y + sin - cos);
        context.closePath();
      }
      context.fillStyle = d.kind === 'ball' ? '#ff5d8f' : '#5df2ff';
      context.strokeStyle = '#101010';
      context.fill();
      context.stroke();
    }
    context.restore();
  }
}
