// The page's controls: the time slider and keys, play / pause and speed, the agent whose beliefs
// are shown, the layer switches, the legend, and the mouse on the map (drag to pan, wheel to
// zoom, double-click to fit, click to select) and on the timeline (click to seek).
/* global CanopyReplay */
(function () {
  "use strict";

  function element(tag, attributes, text) {
    const e = document.createElement(tag);
    Object.keys(attributes || {}).forEach(function (key) { e.setAttribute(key, attributes[key]); });
    if (text !== undefined) e.textContent = text;
    return e;
  }

  // Steps per second to offer: fractions of real time (1/dt steps/s) and 60 steps/s.
  function speeds(run) {
    const real = 1 / run.dt, out = [];
    [0.25, 0.5, 1, 2, 4].forEach(function (f) {
      out.push({ rate: f * real, label: f + "\u00d7 (" + +(f * real).toPrecision(3) + " steps/s)" });
    });
    out.push({ rate: 60, label: "60 steps/s" });
    return out;
  }

  // A small swatch drawn with the map's own drawing code, for the legend.
  function swatch(draw) {
    const c = element("canvas", { width: 26, height: 18 });
    c.style.width = "26px";
    c.style.height = "18px";
    draw(c.getContext("2d"));
    return c;
  }

  function buildLegend(app) {
    const box = document.getElementById("legend"), run = app.run, C = CanopyReplay.COLOURS;
    function entry(draw, text) {
      const row = element("div");
      row.appendChild(swatch(draw));
      row.appendChild(element("span", {}, text));
      box.appendChild(row);
    }
    // Up to 8 agents one entry each; more in one entry, a colour each (the map's names and the
    // "beliefs of" list tell which is which).
    if (run.agents.length > 8) {
      const uavs = run.agents.filter(function (a) { return a.kind !== "ground"; }).length;
      entry(function (ctx) {
        run.agents.forEach(function (agent, i) {
          ctx.fillStyle = agent.colour;
          ctx.fillRect(1 + (i % 8) * 3, 1 + Math.floor(i / 8) % 8 * 2, 3, 2);
        });
      }, run.agents.length + " agents (" + uavs + " UAVs), one colour each; dart and footprint in its colour");
    }
    run.agents.forEach(function (agent) {
      if (run.agents.length > 8) return;
      entry(function (ctx) {
        ctx.fillStyle = CanopyReplay.rgba(agent.colour, 0.235);
        ctx.fillRect(1, 1, 24, 16);
        ctx.strokeStyle = agent.colour;
        ctx.lineWidth = 1.5;
        ctx.strokeRect(1.5, 1.5, 23, 15);
        CanopyReplay.dart(ctx, { x: 13, y: 9 }, Math.PI / 2, 12, agent.colour);
      }, agent.name + (agent.kind === "ground" ? " (ground robot, sector camera)" : " (UAV, footprint)"));
    });
    entry(function (ctx) {
      ctx.strokeStyle = C.trail; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(2, 15); ctx.lineTo(13, 9); ctx.stroke();
      ctx.beginPath(); ctx.arc(13, 9, 5, 0, 2 * Math.PI); ctx.fillStyle = C.target; ctx.fill();
      ctx.strokeStyle = C.white; ctx.lineWidth = 1.5; ctx.stroke();
    }, "person (true position) and last 5 s");
    entry(function (ctx) {
      ctx.beginPath(); ctx.arc(13, 9, 7, 0, 2 * Math.PI); ctx.fillStyle = C.treeFill; ctx.fill();
      ctx.strokeStyle = C.treeEdge; ctx.lineWidth = 1; ctx.stroke();
    }, "tree crown or wall (truth)");
    if (run.anyContact) {
      entry(function (ctx) {
        ctx.beginPath(); ctx.arc(13, 9, 6, 0, 2 * Math.PI);
        ctx.strokeStyle = C.contact; ctx.lineWidth = 2.5; ctx.stroke();
      }, "agent touching a trunk, wall or agent");
    }
    entry(function (ctx) {
      ctx.fillStyle = C.shadow; ctx.fillRect(1, 1, 24, 16);
    }, "hidden from a line-of-sight camera");
    entry(function (ctx) {
      ctx.strokeStyle = "rgb(70,70,70)"; ctx.lineWidth = 1.5;
      ctx.beginPath(); ctx.ellipse(13, 9, 10, 6, 0, 0, 2 * Math.PI); ctx.stroke();
      ctx.beginPath(); ctx.moveTo(9, 5); ctx.lineTo(17, 13); ctx.moveTo(17, 5); ctx.lineTo(9, 13);
      ctx.lineWidth = 2.5; ctx.stroke();
    }, "fused track and its 2\u03c3 ellipse");
    entry(function (ctx) {
      ctx.strokeStyle = "rgb(70,70,70)"; ctx.lineWidth = 1.2;
      ctx.beginPath(); ctx.arc(13, 9, 6, 0, 2 * Math.PI); ctx.stroke();
    }, "tree in the occlusion map");
    entry(function (ctx) {
      ctx.strokeStyle = "rgb(70,70,70)"; ctx.lineWidth = 1.5;
      ctx.beginPath(); ctx.moveTo(2, 9); ctx.lineTo(22, 9); ctx.stroke();
      ctx.beginPath(); ctx.arc(22, 9, 2.5, 0, 2 * Math.PI); ctx.fillStyle = "rgb(70,70,70)"; ctx.fill();
    }, "plan (each agent's own)");
    entry(function (ctx) {
      ctx.setLineDash([3, 3]); ctx.strokeStyle = "rgb(70,70,70)"; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(2, 9); ctx.lineTo(24, 9); ctx.stroke();
    }, "intention planned against (dashed); orange: late or out of range");
    entry(function (ctx) {
      ctx.strokeStyle = C.lost; ctx.lineWidth = 2;
      ctx.beginPath(); ctx.moveTo(7, 3); ctx.lineTo(19, 15); ctx.moveTo(19, 3); ctx.lineTo(7, 15); ctx.stroke();
    }, "intention lost (sender in range)");
    entry(function (ctx) {
      ctx.setLineDash([6, 4]); ctx.strokeStyle = C.link; ctx.lineWidth = 1.5;
      ctx.beginPath(); ctx.moveTo(1, 9); ctx.lineTo(25, 9); ctx.stroke();
    }, "communication link in range");
  }

  function buildLayers(app) {
    const box = document.getElementById("layers");
    CanopyReplay.LAYERS.forEach(function (layer, n) {
      const label = element("label");
      const input = element("input", { type: "checkbox", id: "layer-" + layer.id });
      input.checked = app.state.layers[layer.id];
      input.addEventListener("change", function () { app.setLayer(layer.id, input.checked); });
      label.appendChild(input);
      label.appendChild(document.createTextNode(" " + (n + 1) + " \u00b7 " + layer.label));
      box.appendChild(label);
    });
  }

  function hit(app, sx, sy) {
    const run = app.run, view = app.view, k = app.state.k;
    let best = null, bestD = Infinity;
    function consider(kind, index, q, radius) {
      const s = view.toScreen(q.x, q.y), d = Math.hypot(s.x - sx, s.y - sy);
      if (d <= radius && d < bestD) { best = { kind: kind, index: index }; bestD = d; }
    }
    for (let i = 0; i < run.agents.length; i++) consider("agent", i, run.uav(k, i), 12);
    if (app.state.layers.truth) {
      for (let t = 0; t < run.targets.length; t++) consider("target", t, run.target(k, t), 10);
    }
    return best;
  }

  function bindMap(app) {
    const canvas = app.view.canvas;
    let drag = null;
    canvas.addEventListener("pointerdown", function (e) {
      drag = { x: e.clientX, y: e.clientY, moved: false };
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener("pointermove", function (e) {
      if (!drag) {
        const rect = canvas.getBoundingClientRect();
        app.hover(e.clientX - rect.left, e.clientY - rect.top);
        return;
      }
      const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      if (!drag.moved && Math.hypot(dx, dy) < 3) return;
      drag.moved = true;
      app.view.pan(dx, dy);
      drag.x = e.clientX;
      drag.y = e.clientY;
      app.draw();
    });
    canvas.addEventListener("pointerup", function (e) {
      const wasClick = drag && !drag.moved;
      drag = null;
      if (!wasClick) return;
      const rect = canvas.getBoundingClientRect();
      const found = hit(app, e.clientX - rect.left, e.clientY - rect.top);
      if (found) app.select(found);
    });
    canvas.addEventListener("wheel", function (e) {
      e.preventDefault();
      const rect = canvas.getBoundingClientRect();
      app.view.zoom(Math.exp(-e.deltaY * 0.0015), e.clientX - rect.left, e.clientY - rect.top);
      app.draw();
    }, { passive: false });
    canvas.addEventListener("pointerleave", function () { app.hover(null, null); });
    canvas.addEventListener("dblclick", function () { app.fit(); });
  }

  function bindKeys(app) {
    document.addEventListener("keydown", function (e) {
      if (e.target && (e.target.tagName === "SELECT" || e.target.tagName === "INPUT") &&
          e.target.type !== "range" && e.target.type !== "checkbox") return;
      const stride = e.shiftKey ? app.run.planSteps : 1;
      let handled = true;
      if (e.key === " ") {
        app.togglePlay();
      } else if (e.key === "ArrowRight") {
        app.pause(); app.setStep(app.state.k + stride);
      } else if (e.key === "ArrowLeft") {
        app.pause(); app.setStep(app.state.k - stride);
      } else if (e.key === "Home") {
        app.setStep(0);
      } else if (e.key === "End") {
        app.setStep(app.run.steps - 1);
      } else if (e.key === "f") {
        app.fit();
      } else if (e.key === "o" && app.state.second) {
        app.setSecond(!app.state.second.on);
      } else if (/^[1-9]$/.test(e.key) && +e.key <= CanopyReplay.LAYERS.length) {
        const id = CanopyReplay.LAYERS[+e.key - 1].id;
        app.setLayer(id, !app.state.layers[id]);
      } else {
        handled = false;
      }
      if (handled) e.preventDefault();
    });
  }

  CanopyReplay.bindControls = function (app) {
    const run = app.run;
    const slider = document.getElementById("slider");
    slider.max = String(run.steps - 1);
    slider.addEventListener("input", function () { app.pause(); app.setStep(+slider.value); });
    const speed = document.getElementById("speed");
    speeds(run).forEach(function (s, n) {
      const option = element("option", { value: String(s.rate) }, s.label);
      if (n === 2) option.selected = true;
      speed.appendChild(option);
    });
    app.state.rate = +speed.value;
    speed.addEventListener("change", function () { app.state.rate = +speed.value; });
    document.getElementById("play").addEventListener("click", function () { app.togglePlay(); });
    const agent = document.getElementById("agent");
    run.agents.forEach(function (a, i) {
      agent.appendChild(element("option", { value: String(i) }, a.name));
    });
    agent.addEventListener("change", function () { app.setAgent(+agent.value); });
    const timeline = document.getElementById("timeline");
    timeline.addEventListener("click", function (e) {
      const rect = timeline.getBoundingClientRect();
      app.pause();
      app.setStep(app.timeline.stepAt(e.clientX - rect.left, rect.width));
    });
    const plot = document.getElementById("plot-field");
    plot.addEventListener("change", function () { app.setPlot(plot.value); });
    CanopyReplay.bindExport(app);
    buildLayers(app);
    buildLegend(app);
    bindMap(app);
    bindKeys(app);
    window.addEventListener("resize", function () { if (app.view.resize()) app.fit(); });
  };
})();
