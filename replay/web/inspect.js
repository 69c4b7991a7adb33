// What the page tells of a place, an agent or a person at one step: the hover readout (the point
// under the cursor in metres, the nearest agent and person and their distances, and the nearest
// track of the shown agent's beliefs: its mean, covariance and distance) and the numbers of the
// selected agent (its plan and cost at the planning epoch in force, the messages it sent and
// the teammates' plans it held, the tracks it holds) or person (where it is, the shown agent's
// track of it and that track's error).
/* global CanopyReplay */
(function () {
  "use strict";

  function fixed(v, digits) {
    return typeof v === "number" && isFinite(v) ? v.toFixed(digits) : "n/a";
  }

  // Squared Mahalanobis distance of (dx, dy) under P = [[pxx, pxy], [pxy, pyy]]:
  // d² = [dx dy] P⁻¹ [dx dy]ᵀ = (pyy dx² − 2 pxy dx dy + pxx dy²) / (pxx pyy − pxy²).
  function mahalanobis2(dx, dy, pxx, pxy, pyy) {
    const det = pxx * pyy - pxy * pxy;
    return det > 0 ? (pyy * dx * dx - 2 * pxy * dx * dy + pxx * dy * dy) / det : NaN;
  }
  CanopyReplay.mahalanobis2 = mahalanobis2;

  // The nearest of `count` points (get(n) → {x, y}) to (x, y): {index, distance}, or null.
  function nearest(count, get, x, y) {
    let best = null;
    for (let n = 0; n < count; n++) {
      const q = get(n), d = Math.hypot(q.x - x, q.y - y);
      if (!best || d < best.distance) best = { index: n, distance: d };
    }
    return best;
  }

  // The hover readout at the world point (x, y) (m) at step k through agent a's beliefs.
  CanopyReplay.hoverAt = function (run, k, a, x, y) {
    const out = { x: x, y: y, agent: null, person: null, track: null };
    const agent = nearest(run.agents.length, function (i) { return run.uav(k, i); }, x, y);
    if (agent) out.agent = { index: agent.index, name: run.agents[agent.index].name, distance: agent.distance };
    const person = nearest(run.targets.length, function (t) { return run.target(k, t); }, x, y);
    if (person) out.person = { index: person.index, name: run.targets[person.index].name, distance: person.distance };
    const tracks = run.tracksAt(k, a);
    const track = nearest(tracks.length, function (j) { return tracks[j]; }, x, y);
    if (track) {
      const t = tracks[track.index];
      out.track = { index: track.index, key: t.key, label: t.label, owner: run.agents[a].name,
        mean: [t.x, t.y, t.vx, t.vy], P: [t.pxx, t.pxy, t.pyy], distance: track.distance,
        mahalanobis: Math.sqrt(mahalanobis2(x - t.x, y - t.y, t.pxx, t.pxy, t.pyy)) };
    }
    return out;
  };

  CanopyReplay.hoverText = function (h) {
    const lines = ["x = " + fixed(h.x, 2) + " m   y = " + fixed(h.y, 2) + " m"];
    const near = [];
    if (h.agent) near.push("agent " + h.agent.name + " " + fixed(h.agent.distance, 2) + " m");
    if (h.person) near.push("person " + h.person.name + " " + fixed(h.person.distance, 2) + " m");
    if (near.length) lines.push("nearest: " + near.join(" \u00b7 "));
    if (h.track) {
      const t = h.track;
      lines.push(t.owner + "'s track " + t.key + " (" + t.label + "): " + fixed(t.distance, 2) + " m away, " +
        fixed(t.mahalanobis, 2) + " \u03c3");
      lines.push("  mean (" + fixed(t.mean[0], 2) + ", " + fixed(t.mean[1], 2) + ") m, v (" +
        fixed(t.mean[2], 2) + ", " + fixed(t.mean[3], 2) + ") m/s");
      lines.push("  P = [[" + fixed(t.P[0], 3) + ", " + fixed(t.P[1], 3) + "], [" + fixed(t.P[1], 3) + ", " +
        fixed(t.P[2], 3) + "]] m\u00b2");
    }
    return lines.join("\n");
  };

  // Agent i's numbers at step k. plan: the plan of the planning epoch in force (made at step
  // planK, its cost and actions), or null before the first; sent: the messages it sent at that
  // epoch; held: per teammate, the epoch of its plan i planned against and how it came
  // (CanopyReplay.intentions); tracks: those it holds, with the person each stands for.
  CanopyReplay.agentNumbers = function (run, k, i) {
    const p = run.uav(k, i), e = run.epochAt[k], out = {
      k: k, name: run.agents[i].name, x: p.x, y: p.y, yaw: p.yaw, plan: null, sent: [], held: [],
      tracks: [], inFootprint: run.inFootprint[k][i].length, visible: run.visible[k][i].length
    };
    if (e >= 0) {
      const E = run.epochs[e], part = E.plans.filter(function (q) { return q.agent === i; })[0];
      if (part) out.plan = { epoch: E.epoch, planK: E.k, cost: part.cost, velocities: part.velocities };
      out.sent = E.sent.filter(function (m) { return m.from === i; })
        .map(function (m) { return { about: run.agents[m.agent].name, epoch: m.epoch, actions: m.velocities.length }; });
      out.held = CanopyReplay.intentions(run, k, i).map(function (item) {
        return { from: run.agents[item.from].name, epoch: item.epoch, status: item.status };
      });
    }
    const of = run.trackOfTargetAt(k, i);
    out.tracks = run.tracksAt(k, i).map(function (t, j) {
      const target = of.indexOf(j);
      return { key: t.key, label: t.label, x: t.x, y: t.y, trace: t.pxx + t.pyy,
        person: target >= 0 ? run.targets[target].name : null };
    });
    return out;
  };

  // Person t's numbers at step k, through agent a's beliefs: its position, a's track of it (the
  // one the OSPA assignment gives), the track's error and tr P.
  CanopyReplay.personNumbers = function (run, k, t, a) {
    const q = run.target(k, t), j = run.trackOfTargetAt(k, a)[t], track = j >= 0 ? run.tracksAt(k, a)[j] : null;
    return { k: k, name: run.targets[t].name, x: q.x, y: q.y, agent: run.agents[a].name,
      track: track ? { key: track.key, x: track.x, y: track.y, trace: track.pxx + track.pyy,
        error: Math.hypot(track.x - q.x, track.y - q.y) } : null };
  };

  function element(tag, text, className) {
    const e = document.createElement(tag);
    if (text !== undefined) e.textContent = text;
    if (className) e.className = className;
    return e;
  }

  // Fills the panel `box` with the selection's numbers at step k.
  CanopyReplay.showNumbers = function (box, run, k, selection, a) {
    box.textContent = "";
    if (!selection) {
      box.appendChild(element("div", "Click an agent or a person for its numbers at this step."));
      return;
    }
    if (selection.kind === "target") {
      const n = CanopyReplay.personNumbers(run, k, selection.index, a);
      box.appendChild(element("h2", "person " + n.name + " at k = " + k));
      box.appendChild(element("div", "at (" + fixed(n.x, 2) + ", " + fixed(n.y, 2) + ") m", "mono"));
      box.appendChild(element("div", n.track
        ? n.agent + "'s track " + n.track.key + ": (" + fixed(n.track.x, 2) + ", " + fixed(n.track.y, 2) +
          ") m, error " + fixed(n.track.error, 2) + " m, tr P " + fixed(n.track.trace, 3) + " m\u00b2"
        : n.agent + " holds no track of it", "mono"));
      box.dataset.kind = "target";
      box.dataset.error = n.track ? String(n.track.error) : "";
      return;
    }
    const n = CanopyReplay.agentNumbers(run, k, selection.index);
    box.appendChild(element("h2", "agent " + n.name + " at k = " + k));
    box.appendChild(element("div", "at (" + fixed(n.x, 2) + ", " + fixed(n.y, 2) + ") m, heading " +
      fixed(n.yaw * 180 / Math.PI, 1) + "\u00b0", "mono"));
    box.appendChild(element("div", n.plan
      ? "plan of epoch " + n.plan.epoch + " (made at k = " + n.plan.planK + "): cost " + n.plan.cost.toPrecision(6) +
        ", " + n.plan.velocities.length + " actions, first (" + fixed(n.plan.velocities[0] && n.plan.velocities[0].x, 2) +
        ", " + fixed(n.plan.velocities[0] && n.plan.velocities[0].y, 2) + ") m/s"
      : "no plan yet", "mono"));
    box.appendChild(element("div", "sent " + n.sent.length + " message" + (n.sent.length === 1 ? "" : "s") +
      (n.sent.length ? " (plans of " + n.sent.map(function (m) { return m.about; }).join(", ") + ")" : ""), "mono"));
    const status = {};
    n.held.forEach(function (h) { status[h.status] = (status[h.status] || 0) + 1; });
    box.appendChild(element("div", "received (teammates' plans held): " + (n.held.length
      ? Object.keys(status).sort().map(function (s) { return status[s] + " " + s; }).join(", ") : "none"), "mono"));
    box.appendChild(element("div", n.tracks.length + " tracks, " + n.inFootprint + " people in its footprint, " +
      n.visible + " seen", "mono"));
    const list = element("div", undefined, "mono tracks");
    n.tracks.forEach(function (t) {
      list.appendChild(element("div", "track " + t.key + " (" + fixed(t.x, 1) + ", " + fixed(t.y, 1) + ") tr P " +
        fixed(t.trace, 2) + (t.person ? " \u2192 " + t.person : "")));
    });
    box.appendChild(list);
    box.dataset.kind = "agent";
    box.dataset.cost = n.plan ? String(n.plan.cost) : "";
    box.dataset.sent = String(n.sent.length);
    box.dataset.tracks = String(n.tracks.length);
    box.dataset.held = n.held.map(function (h) { return h.from + ":" + h.epoch + ":" + h.status; }).join(",");
  };
})();
