// The timeline below the map: the chosen target's or agent's history over the whole run, with
// a cursor at the current step. A target shows the chosen agent's track of it (tr P of the
// position block), which footprints held it, who saw it, who owned it (m-Ownership, paper
// Def. 1) and the agent's OSPA; an agent shows the same for itself over every target.
/* global CanopyReplay */
(function () {
  "use strict";

  const LEFT = 190;      // CSS px of row labels
  const CHART = 56;      // CSS px of a line chart
  const STRIP = 11;      // CSS px of an on/off strip
  const FONT = "11px 'DejaVu Sans', sans-serif";
  const AXIS = 18;       // CSS px of the time axis, at the bottom

  function precise(v) {
    return typeof v === "number" && isFinite(v) ? v.toPrecision(4) : "n/a";
  }

  function names(run, list) {
    return list.map(function (i) { return run.agents[i].name; });
  }

  function agentsWith(run, table, k, t) {
    const out = [];
    for (let i = 0; i < run.agents.length; i++) {
      if (table[k][i].indexOf(t) >= 0) out.push(i);
    }
    return out;
  }

  // The agents whose footprint held target t at some step, in order.
  function agentsThatHeld(run, t) {
    const out = [];
    for (let i = 0; i < run.agents.length; i++) {
      for (let k = 0; k < run.steps; k++) {
        if (run.inFootprint[k][i].indexOf(t) >= 0 || run.visible[k][i].indexOf(t) >= 0) {
          out.push(i);
          break;
        }
      }
    }
    return out;
  }

  // The targets that agent i's footprint held at some step, in order.
  function targetsHeldBy(run, i) {
    const held = new Set();
    for (let k = 0; k < run.steps; k++) run.inFootprint[k][i].forEach(function (t) { held.add(t); });
    return Array.from(held).sort(function (x, y) { return x - y; });
  }

  // tr P_pos (m²) of agent a's track of target t at every step (NaN without one).
  function targetTrace(run, a, t) {
    const out = new Float64Array(run.steps);
    for (let k = 0; k < run.steps; k++) {
      const j = run.trackOfTargetAt(k, a)[t];
      const track = j >= 0 ? run.tracksAt(k, a)[j] : null;
      out[k] = track ? track.pxx + track.pyy : NaN;
    }
    return out;
  }

  // What the timeline shows for a selection ({kind: "target" | "agent", index}) seen through
  // agent a: a title, a line chart of tr P, strips, a line chart of OSPA, and the readout of a
  // step as {text, fields}.
  CanopyReplay.timelineSeries = function (run, selection, a) {
    const strips = [];
    let title, trace, traceLabel, readout;
    const ospa = run.ospa[a];
    if (selection.kind === "target") {
      const t = selection.index, target = run.targets[t];
      title = "person " + target.name + ", seen through " + run.agents[a].name + "'s beliefs";
      trace = targetTrace(run, a, t);
      traceLabel = "tr P of " + run.agents[a].name + "'s track (m\u00b2)";
      // Only the agents that matter to this person: those whose footprint held it or that saw it
      // at some step (an owner has seen it); the others' rows would stay empty.
      const held = agentsThatHeld(run, t);
      held.forEach(function (i) {
        strips.push({ label: "in footprint of " + run.agents[i].name, colour: run.agents[i].colour,
          on: function (k) { return run.inFootprint[k][i].indexOf(t) >= 0; } });
      });
      held.forEach(function (i) {
        strips.push({ label: "seen by " + run.agents[i].name, colour: run.agents[i].colour,
          on: function (k) { return run.visible[k][i].indexOf(t) >= 0; } });
      });
      if (!held.length) strips.push({ label: "no agent held it", colour: "", on: function () { return false; } });
      if (run.owned) {
        strips.push({ label: "owner (" + run.m + "-ownership)", owners: function (k) {
          return agentsWith(run, run.owned, k, t);
        } });
      }
      readout = function (k) {
        const covered = names(run, agentsWith(run, run.inFootprint, k, t));
        const seen = names(run, agentsWith(run, run.visible, k, t));
        const owners = run.owned ? names(run, agentsWith(run, run.owned, k, t)) : [];
        const fields = {
          k: String(k), target: target.name, agent: run.agents[a].name,
          trace: isNaN(trace[k]) ? "none" : precise(trace[k]),
          covered: covered.join(","), visible: seen.join(","), owners: owners.join(","),
          ospa: precise(ospa[k])
        };
        const text = "k = " + k + "   t = " + run.time(k).toFixed(2) + " s   " + target.name +
          "   tr P (" + fields.agent + "'s track) = " + (isNaN(trace[k]) ? "no track" : fields.trace + " m\u00b2") +
          "\nin footprint of: " + (covered.join(", ") || "none") +
          "   seen by: " + (seen.join(", ") || "nobody") +
          "   owned by: " + (owners.join(", ") || "nobody") +
          "   OSPA of " + fields.agent + " = " + fields.ospa + " m";
        return { text: text, fields: fields };
      };
    } else {
      const i = selection.index, agent = run.agents[i];
      a = i;
      title = "agent " + agent.name + " (" + agent.kind + ")";
      trace = new Float64Array(run.steps);
      for (let k = 0; k < run.steps; k++) {
        trace[k] = run.tracksAt(k, i).reduce(function (s, tr) { return s + tr.pxx + tr.pyy; }, 0);
      }
      traceLabel = "\u03a3 tr P of its tracks (m\u00b2)";
      // Only the people its footprint held at some step (it sees and owns only those).
      const held = targetsHeldBy(run, i);
      held.forEach(function (t) {
        const target = run.targets[t];
        strips.push({ label: target.name + " in its footprint", colour: agent.colour,
          on: function (k) { return run.inFootprint[k][i].indexOf(t) >= 0; } });
      });
      held.forEach(function (t) {
        const target = run.targets[t];
        strips.push({ label: target.name + " seen", colour: agent.colour,
          on: function (k) { return run.visible[k][i].indexOf(t) >= 0; } });
      });
      if (!held.length) strips.push({ label: "nobody in its footprint", colour: "", on: function () { return false; } });
      if (run.owned) {
        held.forEach(function (t) {
          const target = run.targets[t];
          strips.push({ label: target.name + " owned (" + run.m + "-own.)", colour: agent.colour,
            on: function (k) { return run.owned[k][i].indexOf(t) >= 0; } });
        });
      }
      readout = function (k) {
        const targetNames = function (list) {
          return list.map(function (t) { return run.targets[t].name; });
        };
        const fields = {
          k: String(k), agent: agent.name, trace: precise(trace[k]),
          tracks: String(run.tracksAt(k, i).length),
          covered: targetNames(run.inFootprint[k][i]).join(","),
          visible: targetNames(run.visible[k][i]).join(","),
          owners: run.owned ? targetNames(run.owned[k][i]).join(",") : "",
          ospa: precise(run.ospa[i][k])
        };
        const text = "k = " + k + "   t = " + run.time(k).toFixed(2) + " s   " + agent.name +
          ": " + fields.tracks + " tracks, \u03a3 tr P = " + fields.trace + " m\u00b2" +
          "\nin its footprint: " + (fields.covered.replace(/,/g, ", ") || "nobody") +
          "   seen: " + (fields.visible.replace(/,/g, ", ") || "nobody") +
          "   owns: " + (fields.owners.replace(/,/g, ", ") || "nothing") +
          "   OSPA = " + fields.ospa + " m";
        return { text: text, fields: fields };
      };
    }
    return { title: title, trace: trace, traceLabel: traceLabel, strips: strips,
      ospa: ospa, ospaLabel: "OSPA of " + run.agents[a].name + " (m)", readout: readout,
      colour: run.agents[a].colour };
  };

  function Timeline(canvas, run) {
    this.canvas = canvas;
    this.run = run;
    this.series = null;
    this.cache = null;  // the drawn history without its cursor
  }

  Timeline.prototype.height = function () {
    return this.series ? CHART + 8 + this.series.strips.length * STRIP + 8 + CHART + 6 + AXIS : 0;
  };

  // Step k ↔ x (CSS px).
  Timeline.prototype.x = function (k, width) {
    return LEFT + (width - LEFT - 8) * (this.run.steps > 1 ? k / (this.run.steps - 1) : 0);
  };
  Timeline.prototype.stepAt = function (x, width) {
    const f = (x - LEFT) / Math.max(1, width - LEFT - 8);
    return Math.min(this.run.steps - 1, Math.max(0, Math.round(f * (this.run.steps - 1))));
  };

  Timeline.prototype.set = function (series) {
    this.series = series;
    this.cache = null;
    this.canvas.style.height = this.height() + "px";
  };

  // A chart of `values` per step; `second` (a second run's values at the same steps, or none)
  // dashed over it on the same scale.
  function lineChart(ctx, tl, values, top, width, colour, label, second) {
    let max = 0;
    [values, second || []].forEach(function (list) {
      for (let k = 0; k < list.length; k++) if (isFinite(list[k])) max = Math.max(max, list[k]);
    });
    if (!(max > 0)) max = 1;
    ctx.strokeStyle = "rgb(200,200,195)";
    ctx.lineWidth = 1;
    ctx.strokeRect(LEFT + 0.5, top + 0.5, width - LEFT - 8, CHART);
    [values, second].forEach(function (list, n) {
      if (!list) return;
      ctx.beginPath();
      let pen = false;
      for (let k = 0; k < list.length; k++) {
        if (!isFinite(list[k])) { pen = false; continue; }
        const x = tl.x(k, width), y = top + CHART - CHART * list[k] / max;
        if (pen) ctx.lineTo(x, y); else ctx.moveTo(x, y);
        pen = true;
      }
      ctx.strokeStyle = colour;
      ctx.lineWidth = 1.5;
      ctx.setLineDash(n ? [5, 3] : []);
      ctx.stroke();
      ctx.setLineDash([]);
    });
    ctx.fillStyle = "rgb(20,20,20)";
    ctx.fillText(label, 4, top + 12);
    ctx.fillStyle = "rgb(90,90,90)";
    ctx.fillText("max " + max.toPrecision(3), 4, top + 26);
    if (second) ctx.fillText("dashed: run B", 4, top + 40);
  }

  Timeline.prototype.drawHistory = function (ctx, width) {
    const s = this.series, run = this.run;
    ctx.fillStyle = "rgb(250,250,246)";
    ctx.fillRect(0, 0, width, this.height());
    ctx.font = FONT;
    lineChart(ctx, this, s.trace, 2, width, s.colour, s.traceLabel, s.traceB);
    let top = CHART + 10;
    const self = this;
    s.strips.forEach(function (strip) {
      ctx.fillStyle = "rgb(20,20,20)";
      ctx.fillText(strip.label, 4, top + 9);
      ctx.fillStyle = "rgb(236,236,230)";
      ctx.fillRect(LEFT, top + 1, width - LEFT - 8, STRIP - 2);
      for (let k = 0; k < run.steps; k++) {
        const x0 = self.x(k - 0.5, width), x1 = self.x(k + 0.5, width);
        if (strip.owners) {
          const owners = strip.owners(k);
          owners.forEach(function (i, n) {
            ctx.fillStyle = run.agents[i].colour;
            const h = (STRIP - 2) / owners.length;
            ctx.fillRect(x0, top + 1 + n * h, x1 - x0, h);
          });
        } else if (strip.on(k)) {
          ctx.fillStyle = strip.colour;
          ctx.fillRect(x0, top + 1, x1 - x0, STRIP - 2);
        }
      }
      top += STRIP;
    });
    lineChart(ctx, this, s.ospa, top + 8, width, s.colour, s.ospaLabel);
    this.drawAxis(ctx, width, top + 8 + CHART + 4);
  };

  // The time axis: ticks and labels in seconds, 1, 2 or 5 x 10^n apart, at least 60 px apart.
  Timeline.prototype.drawAxis = function (ctx, width, top) {
    const run = this.run, duration = (run.steps - 1) * run.dt, span = width - LEFT - 8;
    if (!(duration > 0) || !(span > 0)) return;
    const least = 60 * duration / span, decade = Math.pow(10, Math.floor(Math.log10(least)));
    const every = [1, 2, 5, 10].map(function (m) { return m * decade; })
      .filter(function (v) { return v >= least; })[0];
    ctx.strokeStyle = "rgb(90,90,90)";
    ctx.fillStyle = "rgb(20,20,20)";
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(LEFT, top + 0.5);
    ctx.lineTo(LEFT + span, top + 0.5);
    const ticks = [];
    for (let n = 0; n * every <= duration * (1 + 1e-9); n++) {
      const seconds = n * every, x = Math.round(this.x(seconds / run.dt, width)) + 0.5;
      ctx.moveTo(x, top);
      ctx.lineTo(x, top + 4);
      ticks.push({ x: x, text: +seconds.toPrecision(6) + " s" });
    }
    ctx.stroke();
    ctx.textAlign = "center";
    ticks.forEach(function (tick) { ctx.fillText(tick.text, tick.x, top + 15); });
    ctx.textAlign = "left";
    ctx.fillText("time", 4, top + 15);
    this.ticks = ticks;  // what the axis shows, which the tests read
  };

  Timeline.prototype.draw = function (k) {
    const canvas = this.canvas;
    if (!this.series) return;
    const ratio = window.devicePixelRatio || 1;
    const width = Math.max(1, Math.round(canvas.getBoundingClientRect().width)), height = this.height();
    if (canvas.width !== Math.round(width * ratio) || canvas.height !== Math.round(height * ratio)) {
      canvas.width = Math.round(width * ratio);
      canvas.height = Math.round(height * ratio);
      this.cache = null;
    }
    const ctx = canvas.getContext("2d");
    // The history is drawn once into an offscreen canvas and copied under the cursor each step.
    if (!this.cache) {
      this.cache = document.createElement("canvas");
      this.cache.width = canvas.width;
      this.cache.height = canvas.height;
      const c = this.cache.getContext("2d");
      c.setTransform(ratio, 0, 0, ratio, 0, 0);
      this.drawHistory(c, width);
    }
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(this.cache, 0, 0);
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    const x = Math.round(this.x(k, width)) + 0.5;
    ctx.strokeStyle = "rgb(20,20,20)";
    ctx.lineWidth = 1;
    ctx.beginPath();
    ctx.moveTo(x, 0);
    ctx.lineTo(x, height);
    ctx.stroke();
  };

  CanopyReplay.Timeline = Timeline;
})();
