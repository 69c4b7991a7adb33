// The map's projection: world metres → canvas pixels (x right, y up in the world, down on the
// canvas), fitted to a box, moved by dragging and scaled by the wheel about the cursor.
/* global CanopyReplay */
(function () {
  "use strict";

  function View(canvas) {
    this.canvas = canvas;
    this.ratio = 1;       // backing-store pixels per CSS pixel
    this.width = 1;       // CSS px
    this.height = 1;      // CSS px
    this.scale = 1;       // CSS px per m
    this.cx = 0;          // m, the world point at the canvas centre
    this.cy = 0;
  }

  // Matches the canvas's backing store to its CSS size; returns true when it changed.
  View.prototype.resize = function () {
    const rect = this.canvas.getBoundingClientRect();
    const ratio = window.devicePixelRatio || 1;
    const w = Math.max(1, Math.round(rect.width)), h = Math.max(1, Math.round(rect.height));
    if (w === this.width && h === this.height && ratio === this.ratio) return false;
    this.width = w;
    this.height = h;
    this.ratio = ratio;
    this.canvas.width = Math.round(w * ratio);
    this.canvas.height = Math.round(h * ratio);
    return true;
  };

  // Shows the box [x0, y0, x1, y1] (m) whole, centred, with a margin of 4 %.
  View.prototype.fit = function (box) {
    const w = Math.max(box[2] - box[0], 1e-6), h = Math.max(box[3] - box[1], 1e-6);
    this.scale = 0.96 * Math.min(this.width / w, this.height / h);
    this.cx = 0.5 * (box[0] + box[2]);
    this.cy = 0.5 * (box[1] + box[3]);
  };

  // World (m) → CSS px of the canvas.
  View.prototype.toScreen = function (x, y) {
    return {
      x: 0.5 * this.width + (x - this.cx) * this.scale,
      y: 0.5 * this.height - (y - this.cy) * this.scale
    };
  };

  // CSS px of the canvas → world (m).
  View.prototype.toWorld = function (sx, sy) {
    return {
      x: this.cx + (sx - 0.5 * this.width) / this.scale,
      y: this.cy - (sy - 0.5 * this.height) / this.scale
    };
  };

  // World (m) → the backing store's pixel (integer column and row) that holds that point.
  View.prototype.toPixel = function (x, y) {
    const s = this.toScreen(x, y);
    return { x: Math.floor(s.x * this.ratio), y: Math.floor(s.y * this.ratio) };
  };

  View.prototype.pan = function (dx, dy) {  // CSS px
    this.cx -= dx / this.scale;
    this.cy += dy / this.scale;
  };

  // Scales by `factor` keeping the world point under (sx, sy) where it is.
  View.prototype.zoom = function (factor, sx, sy) {
    const before = this.toWorld(sx, sy);
    this.scale = Math.min(Math.max(this.scale * factor, 1e-3), 1e5);
    const after = this.toWorld(sx, sy);
    this.cx += before.x - after.x;
    this.cy += before.y - after.y;
  };

  // The scale bar's length (m): the largest 1, 2 or 5 x 10^n at most a quarter of the width, as
  // the PNG frames choose it (render/scene_builder.cpp, scaleBarLength).
  CanopyReplay.scaleBarLength = function (widthMetres) {
    if (!(widthMetres > 0) || !isFinite(widthMetres)) return 0;
    const limit = 0.25 * widthMetres;
    const decade = Math.pow(10, Math.floor(Math.log10(limit)));
    const steps = [5, 2, 1];
    for (let i = 0; i < steps.length; i++) {
      if (steps[i] * decade <= limit * (1 + 1e-12)) return steps[i] * decade;
    }
    return decade;
  };

  CanopyReplay.scaleBarLabel = function (metres) {
    return metres >= 1000 ? (metres / 1000) + " km" : String(+metres.toPrecision(6)) + " m";
  };

  CanopyReplay.View = View;
})();
