// Plans and intentions: each agent's own planned path, and the teammates' plans an agent planned
// against at an epoch (SMA-NBO), with those that did not reach it marked.
/* global CanopyReplay */
(function () {
  "use strict";

  const C = CanopyReplay.COLOURS, rgba = CanopyReplay.rgba, inRange = CanopyReplay.inRange;
  const pathOf = CanopyReplay.pathOf;
  const FONT = CanopyReplay.FONT;
  const DOT_GAP = 6;  // px

  // A plan's ground points: from `start`, each action's velocity held for one plan period.
  function integrate(run, start, velocities) {
    const period = run.planSteps * run.dt, out = [{ x: start.x, y: start.y }];
    velocities.forEach(function (v) {
      const last = out[out.length - 1];
      out.push({ x: last.x + period * v.x, y: last.y + period * v.y });
    });
    return out;
  }

  // The intentions agent a planned against at the epoch of step k (SMA-NBO), per teammate j:
  // {from, epoch, path, status}. The record says which epoch's plan of j it held (joint_epoch);
  // it expected this epoch's when j planned before it (the messages' order is the planning
  // order), else the one before. status: "ok"; "lost" (held an older one, in range, no
  // latency); "late" (older, with latency); "out of range"; "none" (nothing ever reached it).
  // They depend on the epoch and a only: kept per (epoch, agent) once asked for (a step draws
  // them, and a plot asks for every step).
  function intentions(run, k, a) {
    const e = run.epochAt[k];
    if (!run.intentionsMemo) run.intentionsMemo = new Map();
    const key = e * run.agents.length + a;
    let known = run.intentionsMemo.get(key);
    if (!known) run.intentionsMemo.set(key, known = intentionsAt(run, k, a));
    return known;
  }

  function intentionsAt(run, k, a) {
    const e = run.epochAt[k];
    if (e < 0 || run.algorithm !== "sma") return [];
    const E = run.epochs[e];
    const part = E.plans.filter(function (p) { return p.agent === a; })[0];
    if (!part || !part.jointEpoch) return [];
    const order = E.sent.map(function (m) { return m.from; });
    const out = [];
    for (let j = 0; j < run.agents.length; j++) {
      if (j === a || order.indexOf(j) < 0) continue;
      const held = part.jointEpoch[j];
      const expected = order.indexOf(j) < order.indexOf(a) ? E.epoch : (e > 0 ? run.epochs[e - 1].epoch : -1);
      const item = { from: j, epoch: held, path: null, status: "ok", madeAt: -1 };
      if (held >= 0 && run.epochIndex.has(held)) {
        const source = run.epochs[run.epochIndex.get(held)];
        const message = source.sent.filter(function (m) { return m.from === j && m.agent === j; })[0];
        if (message) {
          item.path = integrate(run, run.uav(source.k, j), message.velocities);
          item.madeAt = source.k;
        }
      }
      if (expected >= 0 && held < expected) {
        const at = run.epochs[run.epochIndex.get(expected)].k;
        if (!inRange(run, run.uav(at, j), run.uav(at, a))) item.status = "out of range";
        else if (run.commLatency > 0) item.status = "late";
        else item.status = "lost";
      } else if (held < 0 && expected < 0) {
        item.status = "none";
      }
      out.push(item);
    }
    return out;
  }
  CanopyReplay.intentions = intentions;

  // What stays the same between planning epochs: each agent's plan from its first planned point
  // on (with a dot at each point, none within DOT_GAP px of the last one drawn), and the
  // intentions agent a planned against with their "intention of k=…" labels (placed where they
  // cover no label placed before them). slow_layers.js keeps this in a cached canvas.
  function drawPlansFixed(ctx, view, run, k, a) {
    ctx.lineWidth = 1.5;
    run.agents.forEach(function (agent, i) {
      const plan = run.paths[i][k];
      if (!plan.length) return;
      const colour = agent.planColour || (agent.planColour = rgba(agent.colour, 0.784));
      pathOf(ctx, view, plan, false);
      ctx.strokeStyle = colour;
      ctx.stroke();
      ctx.beginPath();
      let last = null;
      plan.forEach(function (q) {
        const s = view.toScreen(q.x, q.y);
        if (last && Math.hypot(s.x - last.x, s.y - last.y) < DOT_GAP) return;
        ctx.moveTo(s.x + 2.5, s.y);
        ctx.arc(s.x, s.y, 2.5, 0, 2 * Math.PI);
        last = s;
      });
      ctx.fillStyle = colour;
      ctx.fill();
    });
    ctx.font = FONT;
    const placed = new CanopyReplay.Boxes();
    intentions(run, k, a).forEach(function (item) {
      if (!item.path) return;
      const colour = statusColour(run, item);
      ctx.setLineDash([3, 3]);
      pathOf(ctx, view, item.path, false);
      ctx.strokeStyle = colour;
      ctx.lineWidth = 2;
      ctx.stroke();
      ctx.setLineDash([]);
      const last = item.path[item.path.length - 1], end = view.toScreen(last.x, last.y);
      ctx.fillStyle = colour;
      placedText(ctx, placed, "intention of k=" + item.madeAt, end.x + 4, end.y - 4);
    });
  }

  function statusColour(run, item) {
    return item.status === "ok" ? run.agents[item.from].colour : item.status === "lost" ? C.lost : C.late;
  }

  // `words` at (x, y) where it covers nothing in `placed` (which then holds it); else nothing.
  function placedText(ctx, placed, words, x, y) {
    const box = { x0: x, y0: y - 11, x1: x + CanopyReplay.textWidth(ctx, words, FONT), y1: y + 2 };
    if (placed.hits(box)) return;
    placed.add(box);
    ctx.fillText(words, x, y);
  }

  // The radius (px) of the largest circle about an agent's position inside its 18 px dart, less
  // half the plan's 1.5 px line: the tip-to-corner edge, from (9, 0) to (-9, 7.2), is
  // 9 * 7.2 / hypot(18, 7.2) = 3.34 px from it, the notch's edges 3.28 px (symbols.js, dart).
  CanopyReplay.UNDER_DART_PX = 3.28 - 0.75;

  // What moves at every step: each agent's leg from where it is to its plan's first point, and
  // at each teammate whose intention was lost, late or out of range a cross and its status
  // (placed where they cover no agent and no status placed before them).
  function drawPlansMoving(ctx, view, run, k, a) {
    ctx.lineWidth = 1.5;
    run.agents.forEach(function (agent, i) {
      const plan = run.paths[i][k];
      if (!plan.length) return;
      const p = run.uav(k, i), s = view.toScreen(p.x, p.y), q = view.toScreen(plan[0].x, plan[0].y);
      // A leg within UNDER_DART_PX of the agent lies under its dart (drawn over it): left out.
      if (Math.hypot(q.x - s.x, q.y - s.y) <= CanopyReplay.UNDER_DART_PX) return;
      ctx.beginPath();
      ctx.moveTo(s.x, s.y);
      ctx.lineTo(q.x, q.y);
      ctx.strokeStyle = agent.planColour || (agent.planColour = rgba(agent.colour, 0.784));
      ctx.stroke();
    });
    const marked = intentions(run, k, a).filter(function (item) {
      return item.status !== "ok" && item.status !== "none";
    });
    if (!marked.length) return;
    ctx.font = FONT;
    const placed = new CanopyReplay.Boxes();
    for (let i = 0; i < run.agents.length; i++) {
      const p = run.uav(k, i), s = view.toScreen(p.x, p.y);
      placed.add({ x0: s.x - 10, y0: s.y - 10, x1: s.x + 10, y1: s.y + 10 });
    }
    // The crosses of one colour in one path, stroked once (a city's 63 teammates out of range
    // are 63 crosses a step); then the labels.
    const at = marked.map(function (item) { const p = run.uav(k, item.from); return view.toScreen(p.x, p.y); });
    ctx.lineWidth = 2;
    [C.lost, C.late].forEach(function (colour) {
      ctx.beginPath();
      marked.forEach(function (item, n) {
        if (statusColour(run, item) !== colour) return;
        const s = at[n];
        ctx.moveTo(s.x - 5, s.y - 20); ctx.lineTo(s.x + 5, s.y - 10);
        ctx.moveTo(s.x + 5, s.y - 20); ctx.lineTo(s.x - 5, s.y - 10);
      });
      ctx.strokeStyle = colour;
      ctx.stroke();
    });
    marked.forEach(function (item, n) {
      ctx.fillStyle = statusColour(run, item);
      placedText(ctx, placed, "intention " + item.status, at[n].x + 8, at[n].y - 12);
    });
  }

  function drawPlans(ctx, view, run, k, a) {
    drawPlansFixed(ctx, view, run, k, a);
    drawPlansMoving(ctx, view, run, k, a);
  }
  CanopyReplay.drawPlansFixed = drawPlansFixed;
  CanopyReplay.drawPlansMoving = drawPlansMoving;
  CanopyReplay.drawPlans = drawPlans;
})();
