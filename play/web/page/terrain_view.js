// The landscape as the page draws it: every polygon by id, kept up to date from the world's
// updates (removed ids, added polygons: world.mjs), drawn into an off-screen canvas of which only
// the part an update touched is redrawn. Floating point here is drawing only; the world stays in
// the package's integers.
'use strict';

class TerrainView {
  // box: the world box {x0, y0, x1, y1}; width/height: the canvas in pixels; colour(m): CSS colour.
  constructor(box, width, height, colour) {
    this.box = box;
    this.scale = Math.min(width / (box.x1 - box.x0), height / (box.y1 - box.y0));
    this.colour = colour;
    this.polygons = new Map();  // id -> {material, xy: Int32Array, bbox: [x0, y0, x1, y1]}
    this.canvas = document.createElement('canvas');
    this.canvas.width = width;
    this.canvas.height = height;
    this.context = this.canvas.getContext('2d');
  }

  // World to canvas pixels; north (+y) up.
  px(x) { return (x - this.box.x0) * this.scale; }
  py(y) { return (this.box.y1 - y) * this.scale; }
  // Canvas pixels to the nearest world point.
  worldX(px) { return Math.round(this.box.x0 + px / this.scale); }
  worldY(py) { return Math.round(this.box.y1 - py / this.scale); }

  // Applies one update and redraws what it touched; returns the touched world box or null.
  apply(update) {
    if (update.reset) this.polygons.clear();
    const touched = update.reset ? [this.box.x0, this.box.y0, this.box.x1, this.box.y1] : null;
    let dirty = touched;
    for (const id of update.removed) {
      const old = this.polygons.get(id);
      if (!old) continue;
      dirty = union(dirty, old.bbox);
      this.polygons.delete(id);
    }
    forEachAdded(update, (id, material, xy) => {
      const bbox = boundingBox(xy);
      this.polygons.set(id, {material, xy, bbox});
      dirty = union(dirty, bbox);
    });
    if (dirty) this.redraw(dirty);
    return dirty;
  }

  // Repaints the pixels of a world box: background, then each material as one path (pieces of
  // a material cut at cell lines are one region: no seam shows between them).
  redraw(bbox) {
    const c = this.context;
    const x = Math.floor(this.px(bbox[0])) - 2, y = Math.floor(this.py(bbox[3])) - 2;
    const w = Math.ceil(this.px(bbox[2])) + 2 - x, h = Math.ceil(this.py(bbox[1])) + 2 - y;
    c.save();
    c.beginPath();
    c.rect(x, y, w, h);
    c.clip();
    c.fillStyle = this.colour(0);
    c.fillRect(x, y, w, h);
    const margin = 3 / this.scale;
    const near = [bbox[0] - margin, bbox[1] - margin, bbox[2] + margin, bbox[3] + margin];
    const paths = new Map();
    for (const p of this.polygons.values()) {
      if (!overlaps(p.bbox, near)) continue;
      if (!paths.has(p.material)) paths.set(p.material, new Path2D());
      this.trace(paths.get(p.material), p.xy);
    }
    for (const [material, path] of paths) {
      c.fillStyle = c.strokeStyle = this.colour(material);
      c.fill(path, 'nonzero');
      c.lineWidth = 0.6;  // covers the anti-aliased hairline between two materials' pieces
      c.stroke(path);
    }
    c.restore();
  }

  trace(path, xy) {
    path.moveTo(this.px(xy[0]), this.py(xy[1]));
    for (let k = 2; k < xy.length; k += 2) path.lineTo(this.px(xy[k]), this.py(xy[k + 1]));
    path.closePath();
  }

  draw(context) { context.drawImage(this.canvas, 0, 0); }

  // Outlines of world boxes (cells), e.g. [x0, y0, x1, y1, x0, ...] as an Int32Array.
  drawBoxes(context, boxes, style) {
    context.save();
    context.strokeStyle = style;
    context.lineWidth = 1;
    context.beginPath();
    for (let k = 0; k < boxes.length; k += 4) {
      const x = this.px(boxes[k]), y = this.py(boxes[k + 3]);
      context.rect(x + 0.5, y + 0.5, this.px(boxes[k + 2]) - x, this.py(boxes[k + 1]) - y);
    }
    context.stroke();
    context.restore();
  }
}

// Calls f(id, material, xy) for every polygon an update added (the package's Polygons: flat
// arrays, ids as BigInts).
function forEachAdded(update, f) {
  const p = update.added;
  if (!p) return;
  for (let k = 0; k < p.count; ++k) {
    f(p.ids[k], p.materials[k], p.xy.subarray(2 * p.offsets[k], 2 * p.offsets[k + 1]));
  }
}

function boundingBox(xy) {
  const b = [xy[0], xy[1], xy[0], xy[1]];
  for (let k = 2; k < xy.length; k += 2) {
    b[0] = Math.min(b[0], xy[k]); b[1] = Math.min(b[1], xy[k + 1]);
    b[2] = Math.max(b[2], xy[k]); b[3] = Math.max(b[3], xy[k + 1]);
  }
  return b;
}

function union(a, b) {
  if (!a) return b.slice();
  return [Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[2], b[2]), Math.max(a[3], b[3])];
}

function overlaps(a, b) { return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]; }
