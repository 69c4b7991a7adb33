// The replay page's start: reads the embedded run, draws its first step and keeps the map, the
// slider, the clock and the timeline in step. CanopyReplay.app is the page's state, which the
// browser tests drive and read.
/* global CanopyReplay */
(function () {
  "use strict";

  const started = performance.now();

  // The box (m) the view fits at the start: everything the run visits (agents and people), and
  // the largest footprint's reach about it as far as it lies in the area of interest (beyond it
  // lies nothing of the run's), grown by 3 % of its larger side so that symbols at its edge show
  // whole.
  function runBox(run) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity, reach = 0;
    function add(q) {
      x0 = Math.min(x0, q.x); y0 = Math.min(y0, q.y); x1 = Math.max(x1, q.x); y1 = Math.max(y1, q.y);
    }
    for (let k = 0; k < run.steps; k++) {
      for (let i = 0; i < run.agents.length; i++) add(run.uav(k, i));
      for (let t = 0; t < run.targets.length; t++) add(run.target(k, t));
    }
    run.agents.forEach(function (a) {
      const f = a.footprint;
      reach = Math.max(reach, f.shape === "rectangle" ? 0.5 * Math.hypot(f.size[0], f.size[1]) : f.radius);
    });
    const aoi = run.aoi;
    const bx0 = Math.min(x0, Math.max(x0 - reach, aoi[0])), by0 = Math.min(y0, Math.max(y0 - reach, aoi[1]));
    const bx1 = Math.max(x1, Math.min(x1 + reach, aoi[2])), by1 = Math.max(y1, Math.min(y1 + reach, aoi[3]));
    const pad = 0.03 * Math.max(bx1 - bx0, by1 - by0, 2);
    return [bx0 - pad, by0 - pad, bx1 + pad, by1 + pad];
  }

  function App(run) {
    this.run = run;
    this.view = new CanopyReplay.View(document.getElementById("map"));
    this.ctx = this.view.canvas.getContext("2d");
    this.timeline = new CanopyReplay.Timeline(document.getElementById("timeline"), run);
    this.backdrop = new CanopyReplay.Backdrop(run);
    this.slow = new CanopyReplay.SlowLayers(run);
    this.box = runBox(run);
    const layers = {};
    CanopyReplay.LAYERS.forEach(function (l) { layers[l.id] = true; });
    // plot: the id of the field the timeline's first chart shows (plots.js); null: its first.
    this.state = { k: 0, agent: 0, layers: layers, selection: null, playing: false, rate: 1, plot: null };
    this.pointer = null;  // the cursor on the map (CSS px), for the hover readout
    this.stats = { firstPaintMs: NaN, draws: 0, drawMs: 0, drawMsMax: 0, frames: 0,
      stepsPlayed: 0, frameGaps: [] };
    this.series = null;
  }

  App.prototype.fit = function () {
    this.view.resize();
    this.view.fit(this.box);
    this.draw();
  };

  App.prototype.draw = function () {
    const t0 = performance.now(), s = this.state;
    this.view.resize();
    CanopyReplay.drawMap(this.ctx, this.view, this.run, s, this.backdrop, this.slow);
    document.getElementById("slider").value = String(s.k);
    document.getElementById("clock").textContent = "k = " + s.k + " / " + (this.run.steps - 1) +
      "   t = " + this.run.time(s.k).toFixed(2) + " s" +
      (s.second ? "   (over it k = " + CanopyReplay.secondStep(this.run, s.second.run, s.k) + ")" : "");
    if (this.series) {
      this.timeline.draw(s.k);
      const r = this.series.readout(s.k), out = document.getElementById("readout");
      out.textContent = r.text;
      Object.keys(r.fields).forEach(function (key) { out.dataset[key] = r.fields[key]; });
    }
    CanopyReplay.showNumbers(document.getElementById("numbers"), this.run, s.k, s.selection, s.agent);
    if (s.second) this.showSecondNumbers();
    this.showHover();
    CanopyReplay.noteState(this);
    const ms = performance.now() - t0;
    this.stats.draws++;
    this.stats.drawMs += ms;
    this.stats.drawMsMax = Math.max(this.stats.drawMsMax, ms);
  };

  // Beside A's numbers, those of the second run's counterpart of the selection at its step of
  // the same time, through the beliefs of its counterpart of the shown agent (compare.js).
  App.prototype.showSecondNumbers = function () {
    const s = this.state, second = s.second, box = document.getElementById("numbers-b");
    box.hidden = !second.on;
    if (!second.on) return;
    const k2 = CanopyReplay.secondStep(this.run, second.run, s.k);
    const b = CanopyReplay.counterpartAgent(this.run, second.run, s.agent);
    const selection = CanopyReplay.counterpart(this.run, second.run, s.selection);
    CanopyReplay.showNumbers(box, second.run, k2, b >= 0 ? selection : null, Math.max(b, 0));
    const title = document.createElement("h2");
    title.textContent = CanopyReplay.runTitle(second.run) + ", over it";
    box.insertBefore(title, box.firstChild);
  };

  // The hover readout for the cursor at (sx, sy) CSS px on the map (null: the cursor left it).
  App.prototype.hover = function (sx, sy) {
    this.pointer = sx === null ? null : { x: sx, y: sy };
    this.showHover();
  };

  App.prototype.showHover = function () {
    const box = document.getElementById("hover");
    if (!this.pointer) {
      box.hidden = true;
      return;
    }
    const w = this.view.toWorld(this.pointer.x, this.pointer.y);
    const h = CanopyReplay.hoverAt(this.run, this.state.k, this.state.agent, w.x, w.y);
    box.hidden = false;
    box.textContent = CanopyReplay.hoverText(h);
    box.dataset.x = String(h.x);
    box.dataset.y = String(h.y);
    box.dataset.agent = h.agent ? h.agent.name + ":" + h.agent.distance : "";
    box.dataset.person = h.person ? h.person.name + ":" + h.person.distance : "";
    box.dataset.track = h.track ? [h.track.key, h.track.distance, h.track.mahalanobis].join(":") : "";
    // Over it, the second run's nearest agent, person and track (through its counterpart of the
    // shown agent) at its step of the same time.
    const second = this.state.second, b = second ? CanopyReplay.counterpartAgent(this.run, second.run, this.state.agent) : -1;
    box.dataset.trackB = "";
    if (!second || !second.on || b < 0) return;
    const h2 = CanopyReplay.hoverAt(second.run, CanopyReplay.secondStep(this.run, second.run, this.state.k), b, w.x, w.y);
    box.textContent += "\nrun B (dashed):\n" + CanopyReplay.hoverText(h2).split("\n").slice(1).join("\n");
    box.dataset.trackB = h2.track ? [h2.track.key, h2.track.distance, h2.track.mahalanobis].join(":") : "";
  };

  App.prototype.setStep = function (k) {
    this.state.k = Math.min(this.run.steps - 1, Math.max(0, Math.round(k)));
    this.draw();
  };

  App.prototype.setLayer = function (id, on) {
    this.state.layers[id] = on;
    const box = document.getElementById("layer-" + id);
    if (box) box.checked = on;
    this.draw();
  };

  App.prototype.refreshTimeline = function () {
    const sel = this.state.selection;
    if (!sel) return;
    this.series = CanopyReplay.timelineSeries(this.run, sel, this.state.agent);
    // The first chart plots the chosen field (plots.js), the first one when it has no such.
    const fields = CanopyReplay.plotFields(this.run, sel, this.state.agent);
    const field = fields.filter(function (f) { return f.id === this.state.plot; }, this)[0] || fields[0];
    this.series.trace = field.values();
    this.series.traceLabel = field.label;
    this.series.plot = field.id;
    this.series.traceB = this.secondTrace(field.id);
    const select = document.getElementById("plot-field");
    select.textContent = "";
    fields.forEach(function (f) {
      const option = document.createElement("option");
      option.value = f.id;
      option.textContent = f.label;
      select.appendChild(option);
    });
    select.value = field.id;
    document.getElementById("timeline-title").textContent = this.series.title;
    this.timeline.set(this.series);
  };

  // In an overlay, the same field of the second run's counterpart of the selection (through its
  // counterpart of the shown agent) at each of this run's steps, i.e. at B's step of the same
  // time (compare.js); null without a second run shown or without a counterpart.
  App.prototype.secondTrace = function (id) {
    const s = this.state, second = s.second;
    if (!second || !second.on) return null;
    const b = CanopyReplay.counterpartAgent(this.run, second.run, s.agent);
    const selection = CanopyReplay.counterpart(this.run, second.run, s.selection);
    if (b < 0 || !selection) return null;
    const field = CanopyReplay.plotFields(second.run, selection, b).filter(function (f) { return f.id === id; })[0];
    if (!field) return null;
    const values = field.values(), out = new Float64Array(this.run.steps);
    for (let k = 0; k < this.run.steps; k++) out[k] = values[CanopyReplay.secondStep(this.run, second.run, k)];
    return out;
  };

  App.prototype.setPlot = function (id) {
    this.state.plot = id;
    this.refreshTimeline();
    this.draw();
  };

  App.prototype.setAgent = function (i) {
    this.state.agent = i;
    document.getElementById("agent").value = String(i);
    this.refreshTimeline();
    this.draw();
  };

  // Selects an agent (whose beliefs are then shown) or a target, and shows its timeline.
  App.prototype.select = function (selection) {
    this.state.selection = selection;
    if (selection.kind === "agent") this.state.agent = selection.index;
    document.getElementById("agent").value = String(this.state.agent);
    this.refreshTimeline();
    this.draw();
  };

  App.prototype.pause = function () {
    this.state.playing = false;
    document.getElementById("play").textContent = "\u25b6 play";
  };

  App.prototype.togglePlay = function () {
    if (this.state.playing) return this.pause();
    if (this.state.k >= this.run.steps - 1) this.state.k = 0;
    this.state.playing = true;
    document.getElementById("play").textContent = "\u23f8 pause";
    const app = this;
    let last = null, owed = 0;
    function frame(now) {
      if (!app.state.playing) return;
      if (last !== null) {
        app.stats.frameGaps.push(now - last);
        owed += (now - last) / 1000 * app.state.rate;
      }
      last = now;
      // At most one step per frame (the fastest speed is 60 steps/s): a late frame slows the
      // playback down instead of skipping steps, so every step is drawn.
      if (owed >= 1) {
        owed = Math.min(owed - 1, 1);
        app.stats.stepsPlayed++;
        app.setStep(app.state.k + 1);
      }
      app.stats.frames++;
      if (app.state.k >= app.run.steps - 1) return app.pause();
      requestAnimationFrame(frame);
    }
    requestAnimationFrame(frame);
  };

  // Shows or hides the second run drawn over this one (`canopy view A B --overlay`).
  App.prototype.setSecond = function (on) {
    if (!this.state.second) return;
    this.state.second.on = on;
    document.getElementById("second-on").checked = on;
    this.refreshTimeline();  // its dashed trace
    this.draw();
  };

  // The switch of the second run, and its line in the subtitle.
  function addSecondRun(app, second) {
    app.state.second = { run: second, on: true };
    const a = app.box, b = runBox(second);
    app.box = [Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[2], b[2]), Math.max(a[3], b[3])];
    document.getElementById("subtitle").textContent += " \u00b7 drawn over it: " + CanopyReplay.runTitle(second) +
      " (hollow darts, dashed lines, rings)";
    const numbers = document.createElement("section");
    numbers.id = "numbers-b";
    numbers.setAttribute("aria-live", "polite");
    const first = document.getElementById("numbers");
    first.parentNode.insertBefore(numbers, first.nextSibling);
    const label = document.createElement("label"), input = document.createElement("input");
    input.type = "checkbox";
    input.id = "second-on";
    input.checked = true;
    input.addEventListener("change", function () { app.setSecond(input.checked); });
    label.appendChild(input);
    label.appendChild(document.createTextNode(" o \u00b7 run B (" + (second.folder || second.scenario) + ") drawn over it"));
    document.getElementById("layers").appendChild(label);
  }

  function start(raw, rawSecond) {
    const run = CanopyReplay.decode(raw);
    document.getElementById("scenario").textContent = run.scenario;
    document.getElementById("subtitle").textContent = "seed " + run.seed + " \u00b7 " + run.steps +
      " steps of " + run.dt + " s \u00b7 planner " + run.algorithm + " \u00b7 " + run.agents.length +
      " agents, " + run.targets.length + " people, " + (run.trees.length + run.polygons.length) +
      " trees and walls";
    const app = new App(run);
    CanopyReplay.app = app;
    CanopyReplay.bindControls(app);
    if (rawSecond) addSecondRun(app, CanopyReplay.decode(rawSecond));
    CanopyReplay.markRuns(app);  // which run is which, in a page comparing two (compare.js)
    // A person's timeline from the start, so that the page shows every part of itself at once.
    if (run.targets.length) app.state.selection = { kind: "target", index: 0 };
    app.view.resize();
    app.view.fit(app.box);
    // A link's fragment (share.js) restores its step, layers, view, beliefs, selection and plot.
    CanopyReplay.applyFragment(app, location.hash);
    CanopyReplay.LAYERS.forEach(function (l) { document.getElementById("layer-" + l.id).checked = app.state.layers[l.id]; });
    if (app.state.second) document.getElementById("second-on").checked = app.state.second.on;
    document.getElementById("agent").value = String(app.state.agent);
    app.refreshTimeline();
    app.draw();
    app.stats.firstPaintMs = performance.now() - started;
    app.stats.firstPaintSinceNavigation = performance.now();
    CanopyReplay.warmNames(app.ctx, run, app.view.ratio);
  }

  // Resolves once the first step is drawn (the tests wait for it).
  CanopyReplay.ready = Promise.all([CanopyReplay.readData(), CanopyReplay.readData("replay-data-b")])
    .then(function (data) { start(data[0], data[1]); });
  // A top-level const is no property of the window: a side-by-side page reaches its frames'
  // pages through this one (side_by_side.js).
  window.CanopyReplay = CanopyReplay;
})();
