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

  const MISSING = -2147483648;  // an Int32 column's missing number (replay/columns.h)
  // An Int32 of cm (cm/s) in m (m/s); missing: NaN.
  function centimetres(v) { return v === MISSING ? NaN : v / 100; }

  // Occlusion maps are stored as changes (replay/replay_changes.cpp): per agent and step the
  // entries set and the keys removed. The page keeps the columns (columns.js copies them out of
  // the inflated data) and, per agent, the map at the last step asked for: asked for a later step, it applies
  // the changes up to it; an earlier one, it starts again from the first step (one agent's
  // changes over a city run take about a millisecond). A step's list is sorted by key; a step
  // without changes shares the list of the step before. Made for every step at once, the lists
  // were the largest part of a city run's page memory after the crowns (7.3 MB of 22).
  // → mapAt(a, k): [{key, x, y, r, outline: [{x, y}] | null}] (m).
  function mapLists(c, keys, A, S) {
    // Where the changes of (a, k) start in the set, outline and removed columns (at a * S + k).
    const setAt = new Int32Array(A * S + 1), outlineAt = new Int32Array(A * S + 1), removedAt = new Int32Array(A * S + 1);
    for (let id = 0, set = 0; id < A * S; id++) {
      for (let n = 0; n < c.set_count[id]; n++, set++) outlineAt[id + 1] += c.outline_count[set];
      setAt[id + 1] = setAt[id] + c.set_count[id];
      outlineAt[id + 1] += outlineAt[id];
      removedAt[id + 1] = removedAt[id] + c.removed_count[id];
    }
    const cursors = [];
    for (let a = 0; a < A; a++) cursors.push(null);
    return function (a, k) {
      let cursor = cursors[a];
      if (!cursor || cursor.k > k) cursor = cursors[a] = { k: -1, held: new Map(), list: [] };
      while (cursor.k < k) {
        const id = a * S + (++cursor.k), sets = c.set_count[id], removes = c.removed_count[id];
        let outline = outlineAt[id];
        for (let set = setAt[id]; set < setAt[id + 1]; set++) {
          let corners = null;
          if (c.outline_count[set] > 0) {
            corners = [];
            for (let v = 0; v < c.outline_count[set]; v++, outline++) {
              corners.push({ x: centimetres(c.outline_x[outline]), y: centimetres(c.outline_y[outline]) });
            }
          }
          cursor.held.set(c.set_key[set], {
            key: keys[c.set_key[set]], x: centimetres(c.set_x[set]), y: centimetres(c.set_y[set]), r: centimetres(c.set_r[set]),
            outline: corners
          });
        }
        for (let n = removedAt[id]; n < removedAt[id + 1]; n++) cursor.held.delete(c.removed_key[n]);
        if (sets + removes > 0) {
          const held = cursor.held;
          cursor.list = Array.from(held.keys()).sort(function (p, q) { return p - q; })
            .map(function (key) { return held.get(key); });
        }
      }
      return cursor.list;
    };
  }

  // Points from two columns of cm (cm/s): n of them from index `from`.
  function pointsAt(xs, ys, from, n) {
    const out = [];
    for (let j = from; j < from + n; j++) out.push({ x: centimetres(xs[j]), y: centimetres(ys[j]) });
    return out;
  }

  // Planned paths (replay/replay_changes.cpp): per agent and step the number of points, or -1
  // for the same as the step before (which shares its list). → paths[agent][step].
  function unpackPaths(c, A, S) {
    const paths = [];
    let at = 0;
    for (let a = 0; a < A; a++) {
      const steps = [];
      let current = [];
      for (let k = 0; k < S; k++) {
        const n = c.plan_path_count[a * S + k];
        if (n >= 0) {
          current = pointsAt(c.plan_path_x, c.plan_path_y, at, n);
          at += n;
        }
        steps.push(current);
      }
      paths.push(steps);
    }
    return paths;
  }

  // Planning epochs: each agent's plan with the epochs of the teammates' plans it planned
  // against (joint_epoch), and the messages sent, in the order sent.
  function unpackEpochs(c) {
    const out = [];
    let part = 0, action = 0, joint = 0, message = 0, sentAction = 0;
    for (let e = 0; e < c.epoch_k.length; e++) {
      const plans = [], sent = [];
      for (let n = 0; n < c.epoch_part_count[e]; n++, part++) {
        const actions = c.part_action_count[part], joints = c.part_joint_count[part];
        plans.push({ agent: c.part_agent[part], cost: c.part_cost[part],
          velocities: pointsAt(c.part_vx, c.part_vy, action, actions),
          jointEpoch: Array.from(c.part_joint.subarray(joint, joint + joints)) });
        action += actions;
        joint += joints;
      }
      for (let n = 0; n < c.epoch_message_count[e]; n++, message++) {
        const actions = c.message_action_count[message];
        sent.push({ agent: c.message_agent[message], from: c.message_from[message], epoch: c.message_epoch[message],
          velocities: pointsAt(c.message_vx, c.message_vy, sentAction, actions) });
        sentAction += actions;
      }
      out.push({ k: c.epoch_k[e], epoch: c.epoch_epoch[e], plans: plans, sent: sent });
    }
    return out;
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

  // How many (step, agent) track lists a run keeps made (a step's drawing asks for one agent's,
  // a plot for one agent's at every step).
  const TRACK_LISTS_KEPT = 2048;

  // The tracks of (k, a) as objects, and track_of_target (the index of a's track standing for
  // person t, or -1) as an Int32Array of T, made from the columns when asked and the last
  // TRACK_LISTS_KEPT kept. Made once for the whole run they were a city run's largest part of
  // the page's memory (71 078 objects and an Int32Array of 301 × 64 × 256).
  function trackLists(columns, keys, labels, A, T) {
    const kept = new Map();
    return function (k, a) {
      const id = k * A + a;
      let got = kept.get(id);
      if (got) return got;
      const list = [], of = new Int32Array(T).fill(-1), c = columns;
      for (let j = c.start[id], m = 0; j < c.start[id + 1]; j++, m++) {
        list.push({
          key: keys[c.key[j]], label: labels[c.label[j]],
          x: centimetres(c.x[j]), y: centimetres(c.y[j]), vx: centimetres(c.vx[j]), vy: centimetres(c.vy[j]),
          pxx: c.pxx[j], pxy: c.pxy[j], pyy: c.pyy[j]
        });
        if (c.target[j] >= 0) of[c.target[j]] = m;
      }
      got = { tracks: list, of: of };
      if (kept.size >= TRACK_LISTS_KEPT) kept.delete(kept.keys().next().value);  // the oldest
      kept.set(id, got);
      return got;
    };
  }

  CanopyReplay.decode = function (raw) {
    const A = raw.agents.length, T = raw.targets.length, S = raw.steps, keys = raw.keys;
    // No function kept by the run refers to `raw`, so that the parsed data can be collected.
    // Up to 8 agents keep the frames' colours; more get one colour each.
    if (A > 8) raw.agents.forEach(function (agent, i) { agent.colour = spreadColour(i); });
    const run = {
      scenario: raw.scenario, seed: raw.seed, letter: raw.letter || null, folder: raw.folder || null, dt: raw.dt, steps: S, planSteps: raw.plan_steps,
      plans: raw.plans, algorithm: raw.algorithm, aoi: raw.aoi, occlusionModel: raw.occlusion_model,
      commRange: raw.comm_range, commLatency: raw.comm_latency, commDrop: raw.comm_drop, m: raw.m, agents: raw.agents, targets: raw.targets,
      polygons: raw.polygons.map(points),
      inFootprint: raw.in_footprint, visible: raw.visible, owned: raw.owned, ospa: raw.ospa,
      paths: unpackPaths(raw.planColumns, A, S),
      epochs: unpackEpochs(raw.planColumns),
      epochIndex: new Map(),
      epochAt: new Int32Array(S)
    };
    // The crowns as three Float64Arrays, {length, x, y, r} (100 230 objects were 6.5 MB of a
    // city page's memory).
    run.trees = raw.trees;
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
    const lists = trackLists(raw.trackColumns, keys, raw.labels, A, T);
    // Agent a's tracks at step k ([{key, label, x, y, vx, vy, pxx, pxy, pyy}], m, m/s, m²) and
    // the index of its track of each person (-1: none).
    run.tracksAt = function (k, a) { return lists(k, a).tracks; };
    // Agent a's occlusion map at step k.
    run.mapAt = mapLists(raw.mapColumns, keys, A, S);
    run.trackOfTargetAt = function (k, a) { return lists(k, a).of; };
    return run;
  };
})();
