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
  CanopyReplay.FONT = FONT;

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

  CanopyReplay.pathOf = pathOf;

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
    run.treeGrid.each(p.x - r, p.y - r, p.x + r, p.y + r, function (x, y, rt) {
      if (Math.abs(x - p.x) <= r + rt && Math.abs(y - p.y) <= r + rt) out.push({ x: x, y: y, r: rt });
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

  // A footprint narrower than SHADOW_PX on the screen shows no shadows: they would fill a few
  // pixels at most (a city seen whole), and each costs a clip and a query of the trees.
  const SHADOW_PX = 8;

  function drawSensors(ctx, view, run, k) {
    run.agents.forEach(function (agent, i) {
      const p = run.uav(k, i), f = CanopyReplay.footprintAt(run, k, i), r = reach(f), s = view.toScreen(p.x, p.y), rs = r * view.scale;
      if (s.x + rs < -2 || s.y + rs < -2 || s.x - rs > view.width + 2 || s.y - rs > view.height + 2) return;  // off the map
      const shadows = agent.los && 2 * rs >= SHADOW_PX;
      if (shadows) ctx.save();
      footprintPath(ctx, view, f, p, p.yaw);
      ctx.fillStyle = rgba(agent.colour, 0.235);
      ctx.fill();
      if (shadows) {
        // The shadows of every crown near the footprint, kept inside it.
        ctx.clip();
        ctx.beginPath();
        crownsNear(run, p, r).forEach(function (crown) { addShadow(ctx, view, p, crown, 2 * r + 1); });
        ctx.fillStyle = C.shadow;
        ctx.fill("nonzero");
        ctx.restore();
      }
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

  function drawOcclusionMap(ctx, view, run, k, a) {
    ctx.strokeStyle = run.agents[a].colour;
    ctx.lineWidth = 1.2;
    ctx.beginPath();  // every entry in one path, stroked once
    run.mapAt(a, k).forEach(function (e) {
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
  CanopyReplay.drawOcclusionMap = drawOcclusionMap;

  // A trail lying within TRAIL_HIDDEN_PX of its person's symbol is under the disc (radius 5 px,
  // drawn over it) even with its line's half-width: it is left out, as is a trail wholly off
  // the map. trailStats counts, for the last draw, the trails drawn, those under their disc and
  // those off the map.
  CanopyReplay.TRAIL_HIDDEN_PX = 3.5;
  CanopyReplay.trailStats = { drawn: 0, under: 0, off: 0 };

  function drawTrails(ctx, view, run, k) {
    const first = Math.max(0, k - Math.round(TRAIL_SECONDS / run.dt));
    ctx.strokeStyle = C.trail;
    ctx.lineWidth = 2;
    ctx.lineJoin = "round";
    if (k - first < 1) return;
    const n = k - first + 1, xs = new Float64Array(n), ys = new Float64Array(n), stats = { drawn: 0, under: 0, off: 0 };
    CanopyReplay.trailStats = stats;
    ctx.beginPath();  // every person's trail in one path, stroked once
    for (let t = 0; t < run.targets.length; t++) {
      let far = 0, x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
      for (let j = first; j <= k; j++) {
        const q = run.target(j, t), s = view.toScreen(q.x, q.y);
        xs[j - first] = s.x;
        ys[j - first] = s.y;
        x0 = Math.min(x0, s.x); y0 = Math.min(y0, s.y); x1 = Math.max(x1, s.x); y1 = Math.max(y1, s.y);
      }
      for (let m = 0; m < n; m++) far = Math.max(far, Math.hypot(xs[m] - xs[n - 1], ys[m] - ys[n - 1]));
      if (x1 < -2 || y1 < -2 || x0 > view.width + 2 || y0 > view.height + 2) {
        stats.off++;
        continue;
      }
      if (far <= CanopyReplay.TRAIL_HIDDEN_PX) {
        stats.under++;
        continue;
      }
      stats.drawn++;
      let lx = 0, ly = 0;
      for (let m = 0; m < n; m++) {
        // A point under a pixel from the last one drawn is left out (but never the newest).
        if (m > 0 && m < n - 1 && Math.abs(xs[m] - lx) < 1 && Math.abs(ys[m] - ly) < 1) continue;
        if (m > 0) ctx.lineTo(xs[m], ys[m]); else ctx.moveTo(xs[m], ys[m]);
        lx = xs[m];
        ly = ys[m];
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

  // Agent a's tracks at step k: each a 2σ ellipse, a cross at its mean and a label "track KEY →
  // PERSON" (where it covers no label in style.placed, a CanopyReplay.Boxes, which then holds
  // it). style: a second run's look (second_run.js) or none: {dash: the ellipses' dash, plus:
  // "+" instead of "×", prefix: words before each label, placed}. Returns how many it drew.
  function drawTracks(ctx, view, run, k, a, style) {
    style = style || {};
    const colour = run.agents[a].colour, tracks = run.tracksAt(k, a), of = run.trackOfTargetAt(k, a);
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
    if (style.dash) ctx.setLineDash(style.dash);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.beginPath();
    at.forEach(function (s) {
      if (style.plus) {
        ctx.moveTo(s.x, s.y - 6); ctx.lineTo(s.x, s.y + 6);
        ctx.moveTo(s.x - 6, s.y); ctx.lineTo(s.x + 6, s.y);
      } else {
        ctx.moveTo(s.x - 5, s.y - 5); ctx.lineTo(s.x + 5, s.y + 5);
        ctx.moveTo(s.x + 5, s.y - 5); ctx.lineTo(s.x - 5, s.y + 5);
      }
    });
    ctx.lineCap = "round";
    ctx.strokeStyle = C.white;
    ctx.lineWidth = 4.5;
    ctx.stroke();
    ctx.strokeStyle = colour;
    ctx.lineWidth = 2.5;
    ctx.stroke();
    ctx.lineCap = "butt";
    const placed = style.placed || new CanopyReplay.Boxes();
    ctx.font = FONT;
    ctx.fillStyle = colour;
    tracks.forEach(function (t, j) {
      const s = at[j], target = of.indexOf(j);
      const text = (style.prefix || "") + "track " + t.key + (target >= 0 ? " \u2192 " + run.targets[target].name : "");
      // A label only where it covers none drawn before it.
      const box = { x0: s.x + 7, y0: s.y + 3, x1: s.x + 7 + CanopyReplay.textWidth(ctx, text, FONT), y1: s.y + 16 };
      if (placed.hits(box)) return;
      placed.add(box);
      ctx.fillText(text, s.x + 7, s.y + 14);
    });
    return tracks.length;
  }
  CanopyReplay.drawTracks = drawTracks;

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

  // The clock's panel, top left: the run (with its letter when two are compared), the time and
  // the step; under it the second run drawn over this one and its step, when shown.
  function drawOverlay(ctx, view, run, k, second) {
    ctx.font = FONT;
    const lines = [(run.letter ? "run " + run.letter + ": " : "") + run.scenario + "   t = " + run.time(k).toFixed(2) + " s   k = " + k];
    if (second && second.on) {
      lines.push("run " + (second.run.letter || "B") + " over it (dashed): " + second.run.scenario + "   k = " +
        CanopyReplay.secondStep(run, second.run, k));
    }
    const w = Math.max.apply(null, lines.map(function (l) { return ctx.measureText(l).width; }));
    ctx.fillStyle = C.panel;
    ctx.fillRect(4, 4, w + 10, 6 + 14 * lines.length);
    ctx.strokeStyle = C.panelEdge;
    ctx.lineWidth = 1;
    ctx.strokeRect(4.5, 4.5, w + 9, 5 + 14 * lines.length);
    ctx.fillStyle = C.text;
    lines.forEach(function (l, n) { ctx.fillText(l, 9, 18 + 14 * n); });
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
  // state: {k, agent (whose beliefs), layers: {id: bool}, selection, second: a second run drawn
  // over this one, {run, on}, or none}. With `slow` (a CanopyReplay.SlowLayers of this run,
  // slow_layers.js) the plans' fixed part is copied from its cache; without (an SVG export),
  // drawn.
  CanopyReplay.drawMap = function (ctx, view, run, state, backdrop, slow) {
    const k = state.k, a = state.agent, on = state.layers;
    backdrop.draw(ctx, view, on.trees);
    ctx.lineJoin = "round";
    if (on.sensors) drawSensors(ctx, view, run, k);
    if (on.links) drawLinks(ctx, view, run, k);
    if (on.map) drawOcclusionMap(ctx, view, run, k, a);
    if (on.plans) {
      if (slow && !ctx.vector) slow.draw(ctx, view, state); else CanopyReplay.drawPlansFixed(ctx, view, run, k, a);
      ctx.lineJoin = "round";
      CanopyReplay.drawPlansMoving(ctx, view, run, k, a);
    }
    if (on.truth) drawTrails(ctx, view, run, k);
    // The labels of both runs' tracks placed without overlap (a second run's too, second_run.js).
    const trackLabels = new CanopyReplay.Boxes();
    CanopyReplay.drawnTracks = on.tracks ? drawTracks(ctx, view, run, k, a, { placed: trackLabels }) : 0;
    if (on.truth) CanopyReplay.drawTargets(ctx, view, run, k);
    drawSelection(ctx, view, run, k, state.selection);
    CanopyReplay.drawNames(ctx, view, run, k, on.truth);
    CanopyReplay.drawAgents(ctx, view, run, k);
    // A second run over this one (second_run.js), at its step of the same time.
    const second = state.second;
    if (second && second.on) CanopyReplay.drawSecondRun(ctx, view, run, second.run, state, trackLabels);
    drawOverlay(ctx, view, run, k, second);
  };
})();
