// The map's static layers (the ground, the trees and the walls), drawn once into an offscreen
// canvas and again only when the view (pan, zoom, size) or the trees' switch changes; each step
// copies it under the moving layers. Only crowns inside the view are visited (a grid of cells
// finds them), and a crown narrower than LOD_PX device pixels is not drawn as a disc: its area is
// added to a density raster (one value a device pixel), drawn as the crowns' colour with that
// share of the pixel covered as its opacity.
/* global CanopyReplay */
(function () {
  "use strict";

  const LOD_PX = 2;  // device px: a crown's diameter below which it joins the density raster

  // Crowns (discs: trees.x[i], trees.y[i], trees.r[i], m, Float64Arrays of trees.length) binned
  // into square cells of `cell` metres, ~8 crowns a cell.
  function TreeGrid(trees) {
    this.trees = trees;
    this.n = trees.length;
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity, rmax = 0;
    for (let i = 0; i < this.n; i++) {
      x0 = Math.min(x0, trees.x[i]); y0 = Math.min(y0, trees.y[i]); x1 = Math.max(x1, trees.x[i]); y1 = Math.max(y1, trees.y[i]);
      rmax = Math.max(rmax, trees.r[i]);
    }
    this.rmax = rmax;
    if (!this.n) return;
    const area = Math.max((x1 - x0) * (y1 - y0), 1);
    let cell = Math.max(Math.sqrt(8 * area / this.n), 2 * rmax, 1e-3);
    // At most ~2^20 cells whatever the spread.
    cell = Math.max(cell, Math.sqrt(area / (1 << 20)));
    this.cell = cell;
    this.x0 = x0;
    this.y0 = y0;
    this.nx = Math.floor((x1 - x0) / cell) + 1;
    this.ny = Math.floor((y1 - y0) / cell) + 1;
    // Counting sort of the crowns by cell: start[c] .. start[c + 1] index order[].
    const cellOf = new Int32Array(this.n), start = new Int32Array(this.nx * this.ny + 1);
    for (let i = 0; i < this.n; i++) {
      const c = Math.floor((trees.y[i] - y0) / cell) * this.nx + Math.floor((trees.x[i] - x0) / cell);
      cellOf[i] = c;
      start[c + 1]++;
    }
    for (let c = 0; c < this.nx * this.ny; c++) start[c + 1] += start[c];
    const fill = start.slice(0, this.nx * this.ny), order = new Int32Array(this.n);
    for (let i = 0; i < this.n; i++) order[fill[cellOf[i]]++] = i;
    this.start = start;
    this.order = order;
  }

  // Calls visit(x, y, r) for every crown that may reach into the box [x0, x1] × [y0, y1] (m)
  // (those of the cells the box grown by the largest radius touches); returns how many.
  TreeGrid.prototype.each = function (x0, y0, x1, y1, visit) {
    if (!this.n) return 0;
    const g = this, r = this.rmax;
    const i0 = Math.max(0, Math.floor((x0 - r - g.x0) / g.cell)), i1 = Math.min(g.nx - 1, Math.floor((x1 + r - g.x0) / g.cell));
    const j0 = Math.max(0, Math.floor((y0 - r - g.y0) / g.cell)), j1 = Math.min(g.ny - 1, Math.floor((y1 + r - g.y0) / g.cell));
    let n = 0;
    for (let j = j0; j <= j1; j++) {
      for (let i = i0; i <= i1; i++) {
        const c = j * g.nx + i;
        for (let s = g.start[c]; s < g.start[c + 1]; s++) {
          const t = g.order[s];
          visit(g.trees.x[t], g.trees.y[t], g.trees.r[t]);
          n++;
        }
      }
    }
    return n;
  };
  CanopyReplay.TreeGrid = TreeGrid;

  function Backdrop(run) {
    this.run = run;
    this.canvas = document.createElement("canvas");
    this.key = null;
    // What the last render did: renders so far, crowns drawn as discs, crowns in the raster.
    this.stats = { renders: 0, discs: 0, raster: 0, ms: 0 };
  }

  Backdrop.prototype.render = function (view, treesOn) {
    const t0 = performance.now(), canvas = this.canvas;
    if (canvas.width !== view.canvas.width || canvas.height !== view.canvas.height) {
      canvas.width = view.canvas.width;
      canvas.height = view.canvas.height;
    }
    const counts = this.paint(canvas.getContext("2d"), view, treesOn);
    this.stats = { renders: this.stats.renders + 1, discs: counts.discs, raster: counts.raster,
      ms: performance.now() - t0 };
  };

  // Draws the static layers of this view onto ctx (the cache's canvas, or an SVG export's
  // context), returning how many crowns became discs and how many went to the raster.
  Backdrop.prototype.paint = function (ctx, view, treesOn) {
    const run = this.run, C = CanopyReplay.COLOURS;
    const W = view.canvas.width, H = view.canvas.height, ratio = view.ratio;
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.lineJoin = "round";
    CanopyReplay.drawGround(ctx, view, run);
    let discs = 0, raster = 0;
    if (treesOn) {
      const a = view.toWorld(0, view.height), b = view.toWorld(view.width, 0);
      const density = new Float32Array(W * H), px = view.scale * ratio;
      ctx.fillStyle = C.treeFill;
      ctx.strokeStyle = C.treeEdge;
      ctx.lineWidth = 1;
      run.treeGrid.each(a.x, a.y, b.x, b.y, function (x, y, r) {
        const s = view.toScreen(x, y), rs = r * view.scale;
        if (s.x + rs < 0 || s.x - rs > view.width || s.y + rs < 0 || s.y - rs > view.height) return;
        if (2 * r * px >= LOD_PX) {
          ctx.beginPath();
          ctx.arc(s.x, s.y, rs, 0, 2 * Math.PI);
          ctx.fill();
          ctx.stroke();
          discs++;
          return;
        }
        const i = Math.floor(s.x * ratio), j = Math.floor(s.y * ratio);
        if (i < 0 || j < 0 || i >= W || j >= H) return;
        density[j * W + i] += Math.PI * r * r * px * px;
        raster++;
      });
      if (raster) {
        const image = new ImageData(W, H), d = image.data, fill = [92, 150, 72];  // C.treeFill
        for (let p = 0; p < W * H; p++) {
          if (!(density[p] > 0)) continue;
          d[4 * p] = fill[0]; d[4 * p + 1] = fill[1]; d[4 * p + 2] = fill[2];
          d[4 * p + 3] = Math.round(255 * Math.min(1, density[p]));
        }
        const scratch = document.createElement("canvas");
        scratch.width = W;
        scratch.height = H;
        scratch.getContext("2d").putImageData(image, 0, 0);
        ctx.setTransform(1, 0, 0, 1, 0, 0);
        ctx.drawImage(scratch, 0, 0);
        ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
      }
      CanopyReplay.drawWalls(ctx, view, run);
    }
    return { discs: discs, raster: raster };
  };

  // Copies the static layers for this view onto ctx, rendering them first when the view or the
  // trees' switch changed since the last copy.
  Backdrop.prototype.draw = function (ctx, view, treesOn) {
    const key = [view.canvas.width, view.canvas.height, view.ratio, view.scale, view.cx, view.cy,
      treesOn].join(",");
    if (key !== this.key) {
      this.render(view, treesOn);
      this.key = key;
    }
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(this.canvas, 0, 0);
    ctx.setTransform(view.ratio, 0, 0, view.ratio, 0, 0);
  };

  CanopyReplay.Backdrop = Backdrop;
})();
