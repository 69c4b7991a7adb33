// Drawing one step of the run on the map, layer by layer, in the PNG frames' colours and symbols
// (render/colour.h, render/scene_builder.cpp). Draw order, bottom to top: ground, trees,
// footprints and shadows, links, occlusion map, plans and intentions, trails, tracks, people,
// the selection's ring, names, agents (never hidden), then the clock and the scale bar.
/* global CanopyReplay */
(function () {
  "use strict";

  const C = {
    outside: "rgb(186,188,182)", ground: "rgb(238,234,222)", aoiEdge: "rgb(120,120,112)",
    treeFill: "rgb(92,150,72)", treeEdge: "rgb(46,92,38)", target: "rgb(24,24,24)",
    contact: "rgb(214,40,40)",
    trail: "rgba(70,70,70,0.784)", shadow: "rgba(60,60,60,0.275)", text: "rgb(20,20,20)",
    panel: "rgba(250,250,246,0.92)", panelEdge: "rgb(90,90,90)", white: "rgb(255,255,255)",
    link: "rgba(40,40,40,0.55)", late: "rgb(200,110,0)", lost: "rgb(200,0,0)"
  };
  const TRAIL_SECONDS = 5;  // as the frames (render/trails.h)
  const FONT = "11px 'DejaVu Sans', sans-serif";
  const widths = new Map();   // font and text → width (px)
  const sprites = new Map();  // small canvases drawn once and copied: names, a person's disc

  // The sprite under `key`, drawn by draw(c) into a canvas of w × h CSS px at `ratio` device
  // pixels per px the first time it is asked for, and copied from the cache after.
  function cachedSprite(key, w, h, ratio, draw) {
    let sprite = sprites.get(key);
    if (!sprite) {
      sprite = document.createElement("canvas");
      sprite.width = Math.ceil(w * ratio);
      sprite.height = Math.ceil(h * ratio);
      const c = sprite.getContext("2d");
      c.setTransform(ratio, 0, 0, ratio, 0, 0);
      draw(c);
      sprites.set(key, sprite);
    }
    return sprite;
  }

  // The layers a user toggles: key (the keyboard's digit is its place), id and label.
  CanopyReplay.LAYERS = [
    { id: "trees", label: "trees and walls" },
    { id: "truth", label: "people and their trails" },
    { id: "sensors", label: "footprints, sectors, line-of-sight shadows" },
    { id: "tracks", label: "fused tracks, 2\u03c3 ellipses" },
    { id: "map", label: "occlusion map" },
    { id: "plans", label: "plans, intentions received" },
    { id: "links", label: "communication links in range" }
  ];
  CanopyReplay.COLOURS = C;

  function rgba(hex, alpha) {
    const n = parseInt(hex.slice(1), 16);
    return "rgba(" + (n >> 16) + "," + ((n >> 8) & 255) + "," + (n & 255) + "," + alpha + ")";
  }
  CanopyReplay.rgba = rgba;

  // The footprint's outline as world points (a disc: null), placed at pose p with heading yaw.
  function footprintOutline(f, p, yaw) {
    const c = Math.cos(yaw), s = Math.sin(yaw);
    if (f.shape === "rectangle") {
      const hw = 0.5 * f.size[0], hh = 0.5 * f.size[1];  // w along the heading
      return [[hw, hh], [-hw, hh], [-hw, -hh], [hw, -hh]].map(function (q) {
        return { x: p.x + c * q[0] - s * q[1], y: p.y + s * q[0] + c * q[1] };
      });
    }
    if (f.shape === "quad") {  // a pitched camera's trapezoid: corners in the heading frame
      return f.corners.map(function (q) {
        return { x: p.x + c * q[0] - s * q[1], y: p.y + s * q[0] + c * q[1] };
      });
    }
    if (f.shape === "sector") {
      const half = 0.5 * f.angle, arcs = Math.max(2, Math.ceil(2 * half / (Math.PI / 180)));
      const out = [{ x: p.x, y: p.y }];
      for (let i = 0; i <= arcs; i++) {
        const a = yaw + half * (2 * i / arcs - 1);
        out.push({ x: p.x + f.radius * Math.cos(a), y: p.y + f.radius * Math.sin(a) });
      }
      return out;
    }
    return null;
  }
  CanopyReplay.footprintOutline = footprintOutline;

  function reach(f) {
    return f.shape === "rectangle" ? 0.5 * Math.hypot(f.size[0], f.size[1]) : f.radius;
  }

  function pathOf(ctx, view, pts, closed) {
    ctx.beginPath();
    pts.forEach(function (q, i) {
      const s = view.toScreen(q.x, q.y);
      if (i === 0) ctx.moveTo(s.x, s.y); else ctx.lineTo(s.x, s.y);
    });
    if (closed) ctx.closePath();
  }

  function footprintPath(ctx, view, f, p, yaw) {
    const outline = footprintOutline(f, p, yaw);
    if (outline) {
      pathOf(ctx, view, outline, true);
    } else {
      const s = view.toScreen(p.x, p.y);
      ctx.beginPath();
      ctx.arc(s.x, s.y, f.radius * view.scale, 0, 2 * Math.PI);
    }
  }

  // Adds a polygon to the current path turning counter-clockwise on the screen, so that under
  // the non-zero rule every added shape fills and overlaps fill once.
  function addOriented(ctx, view, pts) {
    const s = pts.map(function (q) { return view.toScreen(q.x, q.y); });
    let area = 0;
    for (let i = 0; i < s.length; i++) {
      const a = s[i], b = s[(i + 1) % s.length];
      area += a.x * b.y - b.x * a.y;
    }
    if (area > 0) s.reverse();
    s.forEach(function (q, i) { if (i === 0) ctx.moveTo(q.x, q.y); else ctx.lineTo(q.x, q.y); });
    ctx.closePath();
  }

  // What a crown hides from a viewer at p, within `far` metres: the crown and the region behind
  // it between the tangents (a disc) or behind each edge (a polygon).
  function addShadow(ctx, view, p, crown, far) {
    if (crown.outline) {
      const v = crown.outline;
      for (let i = 0; i < v.length; i++) {
        const a = v[i], b = v[(i + 1) % v.length];
        const da = Math.hypot(a.x - p.x, a.y - p.y) || 1, db = Math.hypot(b.x - p.x, b.y - p.y) || 1;
        addOriented(ctx, view, [a, b,
          { x: b.x + far * (b.x - p.x) / db, y: b.y + far * (b.y - p.y) / db },
          { x: a.x + far * (a.x - p.x) / da, y: a.y + far * (a.y - p.y) / da }]);
      }
      addOriented(ctx, view, v);
      return;
    }
    const dx = crown.x - p.x, dy = crown.y - p.y, d = Math.hypot(dx, dy);
    const s = view.toScreen(crown.x, crown.y);
    ctx.moveTo(s.x + crown.r * view.scale, s.y);
    ctx.arc(s.x, s.y, crown.r * view.scale, 0, 2 * Math.PI, true);  // counter-clockwise on screen
    ctx.closePath();
    if (d <= crown.r) return;  // the viewer is under the crown: the clip's fill covers it
    const theta = Math.atan2(dy, dx), alpha = Math.asin(crown.r / d), t = Math.sqrt(d * d - crown.r * crown.r);
    const quad = [];
    [theta - alpha, theta + alpha].forEach(function (a) {
      const ux = Math.cos(a), uy = Math.sin(a);
      quad.push({ x: p.x + t * ux, y: p.y + t * uy, ux: ux, uy: uy });
    });
    addOriented(ctx, view, [quad[0], quad[1],
      { x: quad[1].x + far * quad[1].ux, y: quad[1].y + far * quad[1].uy },
      { x: quad[0].x + far * quad[0].ux, y: quad[0].y + far * quad[0].uy }]);
  }

  // The crowns and walls that may reach into the square of half-side r about p (the trees'
  // grid finds the crowns; walls by their boxes).
  function crownsNear(run, p, r) {
    const out = [];
    run.treeGrid.each(p.x - r, p.y - r, p.x + r, p.y + r, function (t) {
      if (Math.abs(t.x - p.x) <= r + t.r && Math.abs(t.y - p.y) <= r + t.r) out.push(t);
    });
    run.polygons.forEach(function (v, n) {
      const b = run.polygonBoxes[n];
      if (v.length === 0 || (b[0] <= p.x + r && b[2] >= p.x - r && b[1] <= p.y + r && b[3] >= p.y - r)) {
        out.push({ outline: v });
      }
    });
    return out;
  }

  function drawGround(ctx, view, run) {
    ctx.fillStyle = C.outside;
    ctx.fillRect(0, 0, view.width, view.height);
    const a = view.toScreen(run.aoi[0], run.aoi[3]), b = view.toScreen(run.aoi[2], run.aoi[1]);
    ctx.fillStyle = C.ground;
    ctx.fillRect(a.x, a.y, b.x - a.x, b.y - a.y);
    ctx.strokeStyle = C.aoiEdge;
    ctx.lineWidth = 1;
    ctx.strokeRect(a.x, a.y, b.x - a.x, b.y - a.y);
  }

  CanopyReplay.drawGround = drawGround;

  // Walls and polygonal crowns (the discs are drawn by the backdrop, backdrop.js).
  function drawWalls(ctx, view, run) {
    ctx.fillStyle = C.treeFill;
    ctx.strokeStyle = C.treeEdge;
    ctx.lineWidth = 1;
    run.polygons.forEach(function (v) {
      pathOf(ctx, view, v, true);
      ctx.fill();
      ctx.stroke();
    });
  }
  CanopyReplay.drawWalls = drawWalls;

  function drawSensors(ctx, view, run, k) {
    run.agents.forEach(function (agent, i) {
      const p = run.uav(k, i), f = agent.footprint;
      ctx.save();
      footprintPath(ctx, view, f, p, p.yaw);
      ctx.fillStyle = rgba(agent.colour, 0.235);
      ctx.fill();
      if (agent.los) {
        // The shadows of every crown near the footprint, kept inside it.
        ctx.clip();
        ctx.beginPath();
        const r = reach(f);
        crownsNear(run, p, r).forEach(function (crown) { addShadow(ctx, view, p, crown, 2 * r + 1); });
        ctx.fillStyle = C.shadow;
        ctx.fill("nonzero");
      }
      ctx.restore();
      footprintPath(ctx, view, f, p, p.yaw);
      ctx.strokeStyle = agent.colour;
      ctx.lineWidth = 1.5;
      ctx.stroke();
    });
  }

  function inRange(run, p, q) {
    return run.commRange === null || Math.hypot(p.x - q.x, p.y - q.y) <= run.commRange;
  }
  CanopyReplay.inRange = inRange;

  function drawLinks(ctx, view, run, k) {
    ctx.strokeStyle = C.link;
    ctx.lineWidth = 1.5;
    ctx.setLineDash([6, 4]);
    ctx.beginPath();  // one path, one stroke: 64 agents have up to 2016 links
    for (let i = 0; i < run.agents.length; i++) {
      const p = run.uav(k, i), a = view.toScreen(p.x, p.y);
      for (let j = i + 1; j < run.agents.length; j++) {
        const q = run.uav(k, j);
        if (!inRange(run, p, q)) continue;
        const b = view.toScreen(q.x, q.y);
        ctx.moveTo(a.x, a.y);
        ctx.lineTo(b.x, b.y);
      }
    }
    ctx.stroke();
    ctx.setLineDash([]);
  }

  function drawMap(ctx, view, run, k, a) {
    ctx.strokeStyle = run.agents[a].colour;
    ctx.lineWidth = 1.2;
    ctx.beginPath();  // every entry in one path, stroked once
    run.maps[a][k].forEach(function (e) {
      if (e.outline) {
        e.outline.forEach(function (o, n) {
          const s = view.toScreen(e.x + o.x, e.y + o.y);
          if (n === 0) ctx.moveTo(s.x, s.y); else ctx.lineTo(s.x, s.y);
        });
        ctx.closePath();
      } else {
        const s = view.toScreen(e.x, e.y), r = Math.max(e.r, 0.1) * view.scale;
        ctx.moveTo(s.x + r, s.y);
        ctx.arc(s.x, s.y, r, 0, 2 * Math.PI);
      }
    });
    ctx.stroke();
  }

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
  function intentions(run, k, a) {
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

  function drawPlans(ctx, view, run, k, a) {
    ctx.lineWidth = 1.5;
    run.agents.forEach(function (agent, i) {
      const plan = run.paths[i][k];
      if (!plan.length) return;
      const colour = rgba(agent.colour, 0.784);
      pathOf(ctx, view, [run.uav(k, i)].concat(plan), false);
      ctx.strokeStyle = colour;
      ctx.stroke();
      ctx.beginPath();
      plan.forEach(function (q) {
        const s = view.toScreen(q.x, q.y);
        ctx.moveTo(s.x + 2.5, s.y);
        ctx.arc(s.x, s.y, 2.5, 0, 2 * Math.PI);
      });
      ctx.fillStyle = colour;
      ctx.fill();
    });
    ctx.font = FONT;
    intentions(run, k, a).forEach(function (item) {
      const from = run.uav(k, item.from), at = view.toScreen(from.x, from.y);
      const colour = item.status === "ok" ? run.agents[item.from].colour : item.status === "lost" ? C.lost : C.late;
      if (item.path) {
        ctx.setLineDash([3, 3]);
        pathOf(ctx, view, item.path, false);
        ctx.strokeStyle = colour;
        ctx.lineWidth = 2;
        ctx.stroke();
        ctx.setLineDash([]);
        const last = item.path[item.path.length - 1], end = view.toScreen(last.x, last.y);
        ctx.fillStyle = colour;
        ctx.fillText("intention of k=" + item.madeAt, end.x + 4, end.y - 4);
      }
      if (item.status !== "ok" && item.status !== "none") {
        ctx.strokeStyle = colour;
        ctx.lineWidth = 2;
        ctx.beginPath();
        ctx.moveTo(at.x - 5, at.y - 20); ctx.lineTo(at.x + 5, at.y - 10);
        ctx.moveTo(at.x + 5, at.y - 20); ctx.lineTo(at.x - 5, at.y - 10);
        ctx.stroke();
        ctx.fillStyle = colour;
        ctx.fillText("intention " + item.status, at.x + 8, at.y - 12);
      }
    });
  }

  function drawTrails(ctx, view, run, k) {
    const first = Math.max(0, k - Math.round(TRAIL_SECONDS / run.dt));
    ctx.strokeStyle = C.trail;
    ctx.lineWidth = 2;
    ctx.lineJoin = "round";
    if (k - first < 1) return;
    ctx.beginPath();  // every person's trail in one path, stroked once
    for (let t = 0; t < run.targets.length; t++) {
      let last = null;
      for (let j = first; j <= k; j++) {
        const q = run.target(j, t), s = view.toScreen(q.x, q.y);
        // A point under a pixel from the last one drawn is left out (but never the newest).
        if (last && j < k && Math.abs(s.x - last.x) < 1 && Math.abs(s.y - last.y) < 1) continue;
        if (last) ctx.lineTo(s.x, s.y); else ctx.moveTo(s.x, s.y);
        last = s;
      }
    }
    ctx.stroke();
  }

  // The 2-sigma ellipse of P = [[a, b], [b, c]]: half-axes 2 sqrt(lambda) along the eigenvectors.
  function ellipse(pxx, pxy, pyy) {
    const mean = 0.5 * (pxx + pyy), d = Math.sqrt(0.25 * (pxx - pyy) * (pxx - pyy) + pxy * pxy);
    return {
      major: 2 * Math.sqrt(Math.max(mean + d, 0)), minor: 2 * Math.sqrt(Math.max(mean - d, 0)),
      angle: 0.5 * Math.atan2(2 * pxy, pxx - pyy)
    };
  }
  CanopyReplay.ellipse = ellipse;

  function drawTracks(ctx, view, run, k, a) {
    const colour = run.agents[a].colour, tracks = run.tracks[k][a], of = run.trackOfTarget[k][a];
    const at = tracks.map(function (t) { return view.toScreen(t.x, t.y); });
    // Ellipses in one path, then the crosses in one (white under the colour), then the labels.
    ctx.beginPath();
    tracks.forEach(function (t, j) {
      const s = at[j], e = ellipse(t.pxx, t.pxy, t.pyy), rx = e.major * view.scale;
      ctx.moveTo(s.x + rx * Math.cos(e.angle), s.y - rx * Math.sin(e.angle));
      ctx.ellipse(s.x, s.y, rx, e.minor * view.scale, -e.angle, 0, 2 * Math.PI);
    });
    ctx.strokeStyle = colour;
    ctx.lineWidth = 1.5;
    ctx.stroke();
    ctx.beginPath();
    at.forEach(function (s) {
      ctx.moveTo(s.x - 5, s.y - 5); ctx.lineTo(s.x + 5, s.y + 5);
      ctx.moveTo(s.x + 5, s.y - 5); ctx.lineTo(s.x - 5, s.y + 5);
    });
    ctx.lineCap = "round";
    ctx.strokeStyle = C.white;
    ctx.lineWidth = 4.5;
    ctx.stroke();
    ctx.strokeStyle = colour;
    ctx.lineWidth = 2.5;
    ctx.stroke();
    ctx.lineCap = "butt";
    const placed = new Boxes();
    ctx.font = FONT;
    ctx.fillStyle = colour;
    tracks.forEach(function (t, j) {
      const s = at[j], target = of.indexOf(j);
      const text = "track " + t.key + (target >= 0 ? " \u2192 " + run.targets[target].name : "");
      // A label only where it covers none drawn before it.
      const box = { x0: s.x + 7, y0: s.y + 3, x1: s.x + 7 + textWidth(ctx, text), y1: s.y + 16 };
      if (placed.hits(box)) return;
      placed.add(box);
      ctx.fillText(text, s.x + 7, s.y + 14);
    });
  }

  function drawTargets(ctx, view, run, k) {
    // A person's disc is drawn once into a small canvas and copied (stroking a few hundred
    // circles a step costs milliseconds).
    const ratio = view.ratio;
    const sprite = cachedSprite("person " + ratio, 14, 14, ratio, function (c) {
      c.beginPath();
      c.arc(7, 7, 5, 0, 2 * Math.PI);
      c.fillStyle = C.target;
      c.fill();
      c.strokeStyle = C.white;
      c.lineWidth = 1.5;
      c.stroke();
    });
    for (let t = 0; t < run.targets.length; t++) {
      const q = run.target(k, t), s = view.toScreen(q.x, q.y);
      ctx.drawImage(sprite, s.x - 7, s.y - 7, sprite.width / ratio, sprite.height / ratio);
    }
  }

  // The frames' dart (render/internal/tessellate.cpp): tip ahead, two back corners, a notch.
  function dart(ctx, s, yaw, size, fill) {
    const h = 0.5 * size, fx = Math.cos(yaw), fy = -Math.sin(yaw), sx = -fy, sy = fx;
    ctx.beginPath();
    ctx.moveTo(s.x + h * fx, s.y + h * fy);
    ctx.lineTo(s.x - h * fx + 0.8 * h * sx, s.y - h * fy + 0.8 * h * sy);
    ctx.lineTo(s.x - 0.45 * h * fx, s.y - 0.45 * h * fy);
    ctx.lineTo(s.x - h * fx - 0.8 * h * sx, s.y - h * fy - 0.8 * h * sy);
    ctx.closePath();
    ctx.fillStyle = fill;
    ctx.fill();
    ctx.strokeStyle = C.target;
    ctx.lineWidth = 1.2;
    ctx.stroke();
  }
  CanopyReplay.dart = dart;

  // An agent's dart (18 px, heading along +x) drawn once per colour into a small canvas and
  // copied turned to its heading: stroking 64 outlines a step costs more than 64 copies.
  function dartSprite(ctx, s, yaw, colour, ratio) {
    const sprite = cachedSprite("dart " + ratio + " " + colour, 24, 24, ratio, function (c) {
      c.lineJoin = "round";
      dart(c, { x: 12, y: 12 }, 0, 18, colour);
    });
    const cos = Math.cos(yaw), sin = Math.sin(yaw);
    // Screen y points down: a heading yaw turns the sprite by -yaw on the screen.
    ctx.setTransform(ratio * cos, -ratio * sin, ratio * sin, ratio * cos, ratio * s.x, ratio * s.y);
    ctx.drawImage(sprite, -12, -12, 24, 24);
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  }

  function drawAgents(ctx, view, run, k) {
    run.agents.forEach(function (agent, i) {
      const p = run.uav(k, i);
      const s = view.toScreen(p.x, p.y);
      dartSprite(ctx, s, p.yaw, agent.colour, view.ratio);
      if (run.contactsAt(k, i)) {  // touching a trunk, wall or agent: a red ring, as the frames
        ctx.beginPath();
        ctx.arc(s.x, s.y, 13, 0, 2 * Math.PI);
        ctx.strokeStyle = C.contact;
        ctx.lineWidth = 2.5;
        ctx.stroke();
      }
    });
  }

  // A name in bold on a white halo, its baseline's left end at (s.x + dx, s.y + dy). Drawn once
  // into a small canvas of its own and copied from there: a few hundred names a step cost
  // copies, not text layout.
  function label(ctx, s, text, dx, dy, ratio) {
    const key = ratio + "\n" + text;
    const sprite = sprites.get(key) || cachedSprite(key, textWidth(ctx, text) + 6, 20, ratio, function (c) {
      c.font = ctx.font;
      c.lineJoin = "round";
      c.lineWidth = 3;
      c.strokeStyle = "rgba(255,255,255,0.8)";
      c.strokeText(text, 3, 15);
      c.fillStyle = C.text;
      c.fillText(text, 3, 15);
    });
    ctx.drawImage(sprite, Math.round((s.x + dx - 3) * ratio) / ratio, Math.round((s.y + dy - 15) * ratio) / ratio,
      sprite.width / ratio, sprite.height / ratio);
  }

  function overlaps(a, b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
  }

  // Screen boxes binned into 64 px cells, so that asking whether a box overlaps any of a few
  // hundred looks at its neighbours only.
  function Boxes() { this.cells = new Map(); }
  Boxes.prototype.each = function (b, visit) {
    for (let j = Math.floor(b.y0 / 64); j <= Math.floor(b.y1 / 64); j++) {
      for (let i = Math.floor(b.x0 / 64); i <= Math.floor(b.x1 / 64); i++) {
        if (visit(j * 65536 + i) === true) return true;  // a number: no string a cell
      }
    }
    return false;
  };
  Boxes.prototype.add = function (b) {
    const cells = this.cells;
    this.each(b, function (key) {
      if (!cells.has(key)) cells.set(key, []);
      cells.get(key).push(b);
    });
  };
  Boxes.prototype.hits = function (b) {
    const cells = this.cells;
    return this.each(b, function (key) {
      const list = cells.get(key);
      return !!list && list.some(function (o) { return overlaps(o, b); });
    });
  };

  // ctx.measureText(text).width in the current font, remembered.
  function textWidth(ctx, text) {
    const key = ctx.font + "\n" + text;
    if (!widths.has(key)) widths.set(key, ctx.measureText(text).width);
    return widths.get(key);
  }

  // Names of people (above right first) and agents (below right first), each at the first of
  // six places around its symbol that covers no agent's or person's symbol and no name placed
  // before it (as the frames place them, render/scene_builder.cpp); where none of the six is
  // free the name is left out (the frames put it at the first place), so a crowd seen from far
  // shows the names that fit instead of a pile.
  function drawNames(ctx, view, run, k, truth) {
    ctx.font = "bold " + FONT;
    ctx.lineJoin = "round";
    const symbols = new Boxes(), placed = new Boxes(), items = [];
    run.agents.forEach(function (agent, i) {
      const p = run.uav(k, i), s = view.toScreen(p.x, p.y);
      symbols.add({ x0: s.x - 10, y0: s.y - 10, x1: s.x + 10, y1: s.y + 10 });
      items.push({ s: s, text: agent.name, gap: 10, aboveFirst: false });
    });
    // People's symbols and names are placed whether shown or not, so that switching them off
    // does not move an agent's name.
    run.targets.forEach(function (target, t) {
      const q = run.target(k, t), s = view.toScreen(q.x, q.y);
      symbols.add({ x0: s.x - 6, y0: s.y - 6, x1: s.x + 6, y1: s.y + 6 });
      items.unshift({ s: s, text: target.name, gap: 6, aboveFirst: true, shown: truth });
    });
    const line = 11;
    items.forEach(function (item) {
      const w = textWidth(ctx, item.text), g = item.gap;
      const aboveRight = [g, -g], belowRight = [g, g + line], aboveLeft = [-g - w, -g],
        belowLeft = [-g - w, g + line], farAbove = [-0.5 * w, -g - line], farBelow = [-0.5 * w, g + 2 * line];
      const places = item.aboveFirst ? [aboveRight, aboveLeft, belowRight, belowLeft, farAbove, farBelow]
        : [belowRight, belowLeft, aboveRight, aboveLeft, farBelow, farAbove];
      let chosen = null;
      for (let n = 0; n < places.length; n++) {
        const b = { x0: item.s.x + places[n][0], y0: item.s.y + places[n][1] - line,
          x1: item.s.x + places[n][0] + w, y1: item.s.y + places[n][1] + 2 };
        if (!symbols.hits(b) && !placed.hits(b)) {
          chosen = places[n];
          break;
        }
      }
      if (!chosen) return;  // no place fits: no name (a crowd at a far zoom)
      placed.add({ x0: item.s.x + chosen[0], y0: item.s.y + chosen[1] - line,
        x1: item.s.x + chosen[0] + w, y1: item.s.y + chosen[1] + 2 });
      if (item.shown !== false) label(ctx, item.s, item.text, chosen[0], chosen[1], view.ratio);
    });
  }

  function drawSelection(ctx, view, run, k, selection) {
    if (!selection) return;
    const q = selection.kind === "target" ? run.target(k, selection.index) : run.uav(k, selection.index);
    const s = view.toScreen(q.x, q.y);
    ctx.beginPath();
    ctx.arc(s.x, s.y, selection.kind === "target" ? 10 : 15, 0, 2 * Math.PI);
    ctx.strokeStyle = C.text;
    ctx.lineWidth = 1.5;
    ctx.setLineDash([3, 2]);
    ctx.stroke();
    ctx.setLineDash([]);
  }

  function drawOverlay(ctx, view, run, k) {
    ctx.font = FONT;
    const text = run.scenario + "   t = " + run.time(k).toFixed(2) + " s   k = " + k;
    const w = ctx.measureText(text).width;
    ctx.fillStyle = C.panel;
    ctx.fillRect(4, 4, w + 10, 20);
    ctx.strokeStyle = C.panelEdge;
    ctx.lineWidth = 1;
    ctx.strokeRect(4.5, 4.5, w + 9, 19);
    ctx.fillStyle = C.text;
    ctx.fillText(text, 9, 18);
    // The scale bar, bottom left.
    const metres = CanopyReplay.scaleBarLength(view.width / view.scale);
    if (!(metres > 0)) return;
    const px = metres * view.scale, x = 12, y = view.height - 12, barLabel = CanopyReplay.scaleBarLabel(metres);
    ctx.fillStyle = C.panel;
    ctx.fillRect(x - 6, y - 24, Math.max(px, ctx.measureText(barLabel).width) + 12, 30);
    ctx.strokeStyle = C.text;
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(x, y - 5); ctx.lineTo(x, y); ctx.lineTo(x + px, y); ctx.lineTo(x + px, y - 5);
    ctx.stroke();
    ctx.fillStyle = C.text;
    ctx.fillText(barLabel, x, y - 9);
  }

  // Draws step k over the static layers of `backdrop` (a CanopyReplay.Backdrop of this run).
  // state: {k, agent (whose beliefs), layers: {id: bool}, selection}.
  CanopyReplay.drawMap = function (ctx, view, run, state, backdrop) {
    const k = state.k, a = state.agent, on = state.layers;
    backdrop.draw(ctx, view, on.trees);
    ctx.lineJoin = "round";
    if (on.sensors) drawSensors(ctx, view, run, k);
    if (on.links) drawLinks(ctx, view, run, k);
    if (on.map) drawMap(ctx, view, run, k, a);
    if (on.plans) drawPlans(ctx, view, run, k, a);
    if (on.truth) drawTrails(ctx, view, run, k);
    if (on.tracks) drawTracks(ctx, view, run, k, a);
    if (on.truth) drawTargets(ctx, view, run, k);
    drawSelection(ctx, view, run, k, state.selection);
    drawNames(ctx, view, run, k, on.truth);
    drawAgents(ctx, view, run, k);
    drawOverlay(ctx, view, run, k);
  };
})();
