// Physics in the page from a real engine: planck.js (a JavaScript port of Box2D, pinned by
// play/web/package-lock.json). The terrain is one static body whose fixtures are the game
// layer's surface chains (solid on their left, each with its two ghost vertices, so the joints
// between cells stay smooth: no seams), replaced per update only where chains changed. Balls,
// boxes and detached debris islands (convex pieces around their centroid) are dynamic bodies.
// Engine units: metres, `unitsPerMetre` world units each, relative to the world box's corner.
'use strict';

class Physics {
  constructor(box, unitsPerMetre) {
    this.box = box;
    this.k = unitsPerMetre;
    this.world = new planck.World({gravity: planck.Vec2(0, -10)});
    this.ground = this.world.createBody();  // the static terrain: one fixture per chain
    this.terrain = new Map();  // chain id -> fixture
    this.dynamic = [];         // {body, kind: 'ball' | 'box', size (world units)}
  }

  metres(x, y) { return planck.Vec2((x - this.box.x0) / this.k, (y - this.box.y0) / this.k); }
  worldPoint(v) { return {x: this.box.x0 + v.x * this.k, y: this.box.y0 + v.y * this.k}; }

  // The terrain's chains of one update (a reset drops all, debris included), and its debris.
  apply(update) {
    if (update.reset) {
      for (const fixture of this.terrain.values()) this.ground.destroyFixture(fixture);
      this.terrain.clear();
      for (const d of this.dynamic) if (d.kind === 'debris') this.world.destroyBody(d.body);
      this.dynamic = this.dynamic.filter(d => d.kind !== 'debris');
    }
    const chains = update.chains;
    for (const id of chains.removed) {
      const fixture = this.terrain.get(id);
      if (fixture) this.ground.destroyFixture(fixture);
      this.terrain.delete(id);
    }
    chains.chains.forEach((chain, k) => this.addChain(chains, chain, k));
    for (const debris of update.debris) this.addDebris(debris);
  }

  // Chain k of the package's chains (solid on its left; an open one with its ghost vertices).
  addChain(chains, {id, closed, ghostPrev, ghostNext}, k) {
    const xy = chains.xy, points = [];
    for (let i = chains.offsets[k]; i < chains.offsets[k + 1]; ++i) {
      points.push(this.metres(xy[2 * i], xy[2 * i + 1]));
    }
    const chain = planck.Chain(points, closed);
    if (!closed) {
      chain.setPrevVertex(this.metres(...ghostPrev));
      chain.setNextVertex(this.metres(...ghostNext));
    }
    this.terrain.set(id, this.ground.createFixture(chain, {friction: 0.6}));
  }

  // A debris island: a body at its exact centroid (rounded to a double here), one polygon
  // fixture per convex piece (at most 8 vertices: what a planck.js polygon takes).
  addDebris({centroid, pieces}) {
    const den = Number(centroid.den);
    const cx = Number(centroid.x) / den, cy = Number(centroid.y) / den;
    const body = this.world.createDynamicBody({position: this.metres(cx, cy)});
    const drawn = pieces.map(({material, points}) => {
      const local = points.map(([x, y]) => planck.Vec2((x - cx) / this.k, (y - cy) / this.k));
      body.createFixture(planck.Polygon(local), {density: 1, friction: 0.6, restitution: 0.1});
      return {material, local};
    });
    this.dynamic.push({body, kind: 'debris', size: 0, pieces: drawn});
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
  // (The border is a wall of the terrain's chains; this only catches what slips through.)
  step(seconds) {
    this.world.step(seconds, 8, 3);
    this.dynamic = this.dynamic.filter(d => {
      if (d.body.getPosition().y > -8) return true;  // 8 m below the world's floor: gone
      this.world.destroyBody(d.body);
      return false;
    });
  }

  drawDebris(context, view, d) {
    for (const piece of d.pieces) {
      context.beginPath();
      piece.local.forEach((v, i) => {
        const p = this.worldPoint(d.body.getWorldPoint(v));
        if (i === 0) context.moveTo(view.px(p.x), view.py(p.y)); else context.lineTo(view.px(p.x), view.py(p.y));
      });
      context.closePath();
      context.fillStyle = context.strokeStyle = view.colour(piece.material);
      context.fill();
      context.stroke();
    }
  }

  // Every dynamic body's centre in world units (for tests and the overlay).
  centres() { return this.dynamic.map(d => this.worldPoint(d.body.getPosition())); }

  draw(context, view) {
    context.save();
    context.lineWidth = 1.5;
    for (const d of this.dynamic) {
      if (d.kind === 'debris') {
        this.drawDebris(context, view, d);
        continue;
      }
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
