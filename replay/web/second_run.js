// A second run (B) drawn over the first (A) on one map and one clock (`canopy view A B
// --overlay`): at A's step k (time t = k dt) B is shown at its step of the same time,
// round(t / dt_B) clamped to its run, with A's layers and through the beliefs of B's agent that
// stands for A's shown one (compare.js: the same name, else the same place): its agents as
// hollow darts, footprints dashed ("sensors"), its shown agent's occlusion map dashed ("map"),
// every agent's plan dashed ("plans"), the shown agent's tracks as "+" with dashed ellipses and
// labels "B track …" ("tracks"), its people as magenta rings ("truth"), and the counterpart of
// A's selection in a magenta dashed ring. A switch (and the key o) shows or hides it.
/* global CanopyReplay */
(function () {
  "use strict";

  const RING = "rgb(200,0,160)";  // the second run's people and selection
  const DASH = [5, 4];

  // The second run's step at the first run's step k.
  CanopyReplay.secondStep = function (run, second, k) {
    return Math.min(second.steps - 1, Math.max(0, Math.round(run.time(k) / second.dt)));
  };

  function drawFootprints(ctx, view, second, k2) {
    ctx.setLineDash(DASH);
    ctx.lineWidth = 1.5;
    second.agents.forEach(function (agent, i) {
      const p = second.uav(k2, i), outline = CanopyReplay.footprintOutline(agent.footprint, p, p.yaw);
      if (outline) {
        CanopyReplay.pathOf(ctx, view, outline, true);
      } else {
        const s = view.toScreen(p.x, p.y);
        ctx.beginPath();
        ctx.arc(s.x, s.y, agent.footprint.radius * view.scale, 0, 2 * Math.PI);
      }
      ctx.strokeStyle = agent.colour;
      ctx.stroke();
    });
    ctx.setLineDash([]);
  }

  // Each agent's planned path from where it is, dashed, a hollow ring at each planned point.
  // Returns the planned points drawn.
  function drawPlans(ctx, view, second, k2) {
    let points = 0;
    ctx.lineWidth = 1.5;
    second.agents.forEach(function (agent, i) {
      const plan = second.paths[i][k2];
      if (!plan.length) return;
      const p = second.uav(k2, i);
      ctx.setLineDash([8, 4]);
      CanopyReplay.pathOf(ctx, view, [{ x: p.x, y: p.y }].concat(plan), false);
      ctx.strokeStyle = CanopyReplay.rgba(agent.colour, 0.784);
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.beginPath();
      plan.forEach(function (q) {
        const s = view.toScreen(q.x, q.y);
        ctx.moveTo(s.x + 3, s.y);
        ctx.arc(s.x, s.y, 3, 0, 2 * Math.PI);
      });
      ctx.stroke();
      points += plan.length;
    });
    return points;
  }

  function drawPeople(ctx, view, second, k2) {
    ctx.beginPath();
    for (let t = 0; t < second.targets.length; t++) {
      const q = second.target(k2, t), s = view.toScreen(q.x, q.y);
      ctx.moveTo(s.x + 5, s.y);
      ctx.arc(s.x, s.y, 5, 0, 2 * Math.PI);
    }
    ctx.strokeStyle = RING;
    ctx.lineWidth = 2;
    ctx.stroke();
  }

  function drawSelection(ctx, view, second, k2, selection) {
    const q = selection.kind === "target" ? second.target(k2, selection.index) : second.uav(k2, selection.index);
    const s = view.toScreen(q.x, q.y);
    ctx.beginPath();
    ctx.arc(s.x, s.y, selection.kind === "target" ? 12 : 17, 0, 2 * Math.PI);
    ctx.strokeStyle = RING;
    ctx.lineWidth = 1.5;
    ctx.setLineDash([2, 3]);
    ctx.stroke();
    ctx.setLineDash([]);
  }

  function drawAgents(ctx, view, second, k2) {
    second.agents.forEach(function (agent, i) {
      const p = second.uav(k2, i), s = view.toScreen(p.x, p.y);
      CanopyReplay.dart(ctx, s, p.yaw, 18, "rgba(255,255,255,0.6)");
      ctx.strokeStyle = agent.colour;  // the dart's path is still the current one
      ctx.lineWidth = 2.5;
      ctx.stroke();
    });
  }

  // What the last draw showed of the second run (the tests read it): its step, the agent whose
  // beliefs (-1: none stands for A's), how many of its tracks, map entries and planned points.
  CanopyReplay.secondStats = null;

  // Draws `second` over `run` at the step of the same time as state.k, with state's layers,
  // beliefs and selection; its track labels placed where they cover none in `placed`.
  CanopyReplay.drawSecondRun = function (ctx, view, run, second, state, placed) {
    const k2 = CanopyReplay.secondStep(run, second, state.k), on = state.layers;
    const b = CanopyReplay.counterpartAgent(run, second, state.agent);
    const selection = CanopyReplay.counterpart(run, second, state.selection);
    const stats = { k: k2, agent: b, tracks: 0, mapEntries: 0, planPoints: 0, selection: selection };
    ctx.lineJoin = "round";
    if (on.sensors) drawFootprints(ctx, view, second, k2);
    if (on.map && b >= 0) {
      ctx.setLineDash(DASH);
      CanopyReplay.drawOcclusionMap(ctx, view, second, k2, b);
      ctx.setLineDash([]);
      stats.mapEntries = second.mapAt(b, k2).length;
    }
    if (on.plans) stats.planPoints = drawPlans(ctx, view, second, k2);
    if (on.tracks && b >= 0) {
      stats.tracks = CanopyReplay.drawTracks(ctx, view, second, k2, b,
        { dash: DASH, plus: true, prefix: (second.letter || "B") + " ", placed: placed });
    }
    if (on.truth) drawPeople(ctx, view, second, k2);
    if (selection) drawSelection(ctx, view, second, k2, selection);
    drawAgents(ctx, view, second, k2);
    CanopyReplay.secondStats = stats;
  };
  CanopyReplay.SECOND_RUN_RING = RING;
})();
