// The run's packed data (replay/replay_data.cpp writes it, columns.js reads it) unpacked into
// per-step values.
// Defines the page's one global, CanopyReplay; the other scripts add to it.
const CanopyReplay = {};

(function () {
  "use strict";

  // Flat [x0, y0, x1, y1, ...] → [{x, y}, ...].
  function points(flat) {
    const out = [];
    for (let i = 0; i + 1 < flat.length; i += 2) out.push({ x: flat[i], y: flat[i + 1] });
    return out;
  }

  // Occlusion maps are stored as changes; every step gets its full list, sorted by key.
  function unpackMaps(changes, keys) {
    const held = new Map();
    let current = [];
    return changes.map(function (change) {
      if (change === 0) return current;
      change[0].forEach(function (e) {
        held.set(e[0], {
          key: keys[e[0]], x: e[1], y: e[2], r: e[3],
          outline: e.length > 4 ? points(e[4]) : null
        });
      });
      change[1].forEach(function (key) { held.delete(key); });
      current = Array.from(held.keys()).sort(function (a, b) { return a - b; })
        .map(function (key) { return held.get(key); });
      return current;
    });
  }

  // Planned paths: 0 means the same as the step before.
  function unpackPaths(steps) {
    let current = [];
    return steps.map(function (s) {
      if (s !== 0) current = points(s);
      return current;
    });
  }

  // Planning epochs: each agent's plan with the epochs of the teammates' plans it planned
  // against (joint_epoch), and the messages sent, in the order sent.
  function unpackEpochs(raw) {
    return raw.map(function (e) {
      return {
        k: e.k, epoch: e.epoch,
        plans: e.agents.map(function (a) {
          return { agent: a[0], cost: a[1], velocities: points(a[2]), jointEpoch: a[3] };
        }),
        sent: e.messages.map(function (m) {
          return { agent: m[0], from: m[1], epoch: m[2], velocities: points(m[3]) };
        })
      };
    });
  }

  // Agents' colours beyond the frames' eight (render/colour.cpp repeats them every 8): 16 hues
  // 22.5 degrees apart at four tones, each tone's hues turned by a further 11.25 degrees, so 64
  // agents get 64 colours (the closest two 24 apart in RGB) and the first 16 differ in hue.
  const TONES = [[0.85, 0.45], [0.75, 0.28], [0.9, 0.68], [0.35, 0.5]];  // saturation, lightness
  function spreadColour(i) {
    const tone = TONES[Math.floor(i / 16) % 4], h = ((i % 16) * 22.5 + Math.floor(i / 16) * 11.25) % 360;
    const a = tone[0] * Math.min(tone[1], 1 - tone[1]);
    const channel = function (n) {
      const k = (n + h / 30) % 12;
      return Math.round(255 * (tone[1] - a * Math.max(-1, Math.min(k - 3, 9 - k, 1))));
    };
    return "#" + [channel(0), channel(8), channel(4)].map(function (v) {
      return (v < 16 ? "0" : "") + v.toString(16);
    }).join("");
  }
  CanopyReplay.spreadColour = spreadColour;

  // track_of_target [k][a][t] (the index of agent a's track standing for person t, or -1) is one
  // Int32Array (columns.js); each [k][a] is a view of its T numbers (indexOf and [t] as an
  // array). As nested arrays it was the largest part of a city run's memory (301 × 64 × 256).
  function trackOfTargetViews(flat, S, A, T) {
    const out = [];
    for (let k = 0; k < S; k++) {
      const perAgent = [];
      for (let a = 0; a < A; a++) perAgent.push(flat.subarray((k * A + a) * T, (k * A + a + 1) * T));
      out.push(perAgent);
    }
    return out;
  }

  CanopyReplay.decode = function (raw) {
    const A = raw.agents.length, T = raw.targets.length, S = raw.steps, keys = raw.keys;
    // No function kept by the run refers to `raw`, so that the parsed data can be collected.
    // Up to 8 agents keep the frames' colours; more get one colour each.
    if (A > 8) raw.agents.forEach(function (agent, i) { agent.colour = spreadColour(i); });
    const run = {
      scenario: raw.scenario, seed: raw.seed, dt: raw.dt, steps: S, planSteps: raw.plan_steps,
      plans: raw.plans, algorithm: raw.algorithm, aoi: raw.aoi, occlusionModel: raw.occlusion_model,
      commRange: raw.comm_range, commLatency: raw.comm_latency, commDrop: raw.comm_drop, m: raw.m, agents: raw.agents, targets: raw.targets,
      trees: [], polygons: raw.polygons.map(points),
      inFootprint: raw.in_footprint, visible: raw.visible, owned: raw.owned, ospa: raw.ospa,
      tracks: raw.tracks,
      trackOfTarget: trackOfTargetViews(raw.track_of_target, S, A, T),
      maps: raw.maps.map(function (changes) { return unpackMaps(changes, keys); }),
      paths: raw.paths.map(unpackPaths),
      epochs: unpackEpochs(raw.epochs),
      epochIndex: new Map(),
      epochAt: new Int32Array(S)
    };
    for (let i = 0; i + 2 < raw.trees.length; i += 3) {
      run.trees.push({ x: raw.trees[i], y: raw.trees[i + 1], r: raw.trees[i + 2] });
    }
    run.treeGrid = new CanopyReplay.TreeGrid(run.trees);  // backdrop.js
    run.polygonBoxes = run.polygons.map(function (v) {
      let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
      v.forEach(function (q) { x0 = Math.min(x0, q.x); y0 = Math.min(y0, q.y); x1 = Math.max(x1, q.x); y1 = Math.max(y1, q.y); });
      return [x0, y0, x1, y1];
    });
    run.epochs.forEach(function (ep, n) { run.epochIndex.set(ep.epoch, n); });
    // planVersion[k]: changes at each step where some agent's planned path (a list kept while
    // unchanged) or the planning epoch changed (slow_layers.js redraws the plans then).
    run.planVersion = new Int32Array(S);
    // epochAt[k]: the index of the last planning epoch at or before step k, -1 before the first.
    let e = -1;
    for (let k = 0; k < S; k++) {
      while (e + 1 < run.epochs.length && run.epochs[e + 1].k <= k) e++;
      run.epochAt[k] = e;
      let changed = k === 0 || e !== run.epochAt[k - 1];
      for (let i = 0; i < A && !changed; i++) changed = run.paths[i][k] !== run.paths[i][k - 1];
      run.planVersion[k] = k === 0 ? 0 : run.planVersion[k - 1] + (changed ? 1 : 0);
    }
    // Poses and positions in typed arrays; the closures keep these, not the raw data.
    const uav = raw.uav, target = raw.target, dt = raw.dt;  // Float64Arrays (columns.js)
    run.uav = function (k, i) {
      const o = (k * A + i) * 3;
      return { x: uav[o], y: uav[o + 1], yaw: uav[o + 2] };
    };
    // Agent i's altitude at step k (m; NaN for one without), or null: no UAV has one (altitude.js).
    const uavZ = raw.uav_z || null;
    run.altitude = uavZ ? function (k, i) { return uavZ[k * A + i]; } : null;
    // What agent i's body touched over step k ("wall:3", "uav:1", …), or null.
    const contacts = new Map();
    (raw.contacts || []).forEach(function (c) { contacts.set(c[0] * A + c[1], c.slice(2)); });
    run.contactsAt = function (k, i) { return contacts.get(k * A + i) || null; };
    run.anyContact = contacts.size > 0;
    run.target = function (k, t) {
      const o = (k * T + t) * 2;
      return { x: target[o], y: target[o + 1] };
    };
    run.time = function (k) { return k * dt; };
    return run;
  };
})();
