// The map's slow layer: the fixed part of the plans (each agent's plan from its first planned
// point on, and the intentions the chosen agent planned against) changes when an agent plans,
// not at every step. It is drawn into an offscreen canvas of the map's size once per view,
// agent and plan version, and copied at every step; what moves at every step (each agent's leg
// to its plan, the marks of a lost intention at its sender) is drawn over it by plans.js. (The
// occlusion map is not cached: its trees' estimates move at most steps.)
/* global CanopyReplay */
(function () {
  "use strict";

  function SlowLayers(run) {
    this.run = run;
    this.canvas = document.createElement("canvas");
    this.key = null;
    this.stats = { renders: 0, copies: 0 };
  }

  // Copies the plans' fixed part at state.k onto ctx, drawing it first when the view, the agent
  // or the plan version (decode.js: run.planVersion, which changes at each step where some
  // agent's plan or the epoch changed) differs from the last copy's.
  SlowLayers.prototype.draw = function (ctx, view, state) {
    const run = this.run, k = state.k, a = state.agent;
    const key = [view.canvas.width, view.canvas.height, view.ratio, view.scale, view.cx, view.cy,
      a, run.planVersion[k]].join(",");
    const canvas = this.canvas;
    if (key !== this.key) {
      if (canvas.width !== view.canvas.width || canvas.height !== view.canvas.height) {
        canvas.width = view.canvas.width;
        canvas.height = view.canvas.height;
      }
      const c = canvas.getContext("2d");
      c.setTransform(1, 0, 0, 1, 0, 0);
      c.clearRect(0, 0, canvas.width, canvas.height);
      c.setTransform(view.ratio, 0, 0, view.ratio, 0, 0);
      c.lineJoin = "round";
      CanopyReplay.drawPlansFixed(c, view, run, k, a);
      this.key = key;
      this.stats.renders++;
    }
    this.stats.copies++;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(canvas, 0, 0);
    ctx.setTransform(view.ratio, 0, 0, view.ratio, 0, 0);
  };

  CanopyReplay.SlowLayers = SlowLayers;
})();
