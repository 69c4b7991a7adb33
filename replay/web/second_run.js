// A second run drawn over the first on one map and one clock (`canopy view A B --overlay`): at
// the first run's step k (time t = k dt) the second is shown at its step of the same time,
// round(t / dt_B) clamped to its run, as outlines over the first run's layers: each agent a
// hollow dart in its colour, its footprint dashed, each person a magenta ring. A switch (and the
// key o) shows or hides it.
/* global CanopyReplay */
(function () {
  "use strict";

  const RING = "rgb(200,0,160)";  // the second run's people

  // The second run's step at the first run's step k.
  CanopyReplay.secondStep = function (run, second, k) {
    return Math.min(second.steps - 1, Math.max(0, Math.round(run.time(k) / second.dt)));
  };

  // Draws `second` at its step k2 with the layers `on` (its footprints with "sensors", its
  // people with "truth"; its agents always).
  CanopyReplay.drawSecondRun = function (ctx, view, second, k2, on) {
    ctx.lineJoin = "round";
    if (on.sensors) {
      ctx.setLineDash([4, 3]);
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
    if (on.truth) {
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
    second.agents.forEach(function (agent, i) {
      const p = second.uav(k2, i), s = view.toScreen(p.x, p.y);
      CanopyReplay.dart(ctx, s, p.yaw, 18, "rgba(255,255,255,0.6)");
      ctx.strokeStyle = agent.colour;  // the dart's path is still the current one
      ctx.lineWidth = 2.5;
      ctx.stroke();
    });
  };
  CanopyReplay.SECOND_RUN_RING = RING;
})();
