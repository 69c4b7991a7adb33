// Sharing a view: the URL's fragment holds the step, the layers, the view (centre and scale),
// the agent whose beliefs are shown, the selection and the plotted field, and opening the page
// with it restores them; the map exports as PNG (its pixels) and as SVG (the same layers drawn
// as shapes and text, svg_context.js).
// Fragment: #k=K&agent=I&sel=a3|t5&layers=trees,truth,…&view=CX,CY,SCALE&plot=FIELD[&second=0|1]
/* global CanopyReplay */
(function () {
  "use strict";

  function exact(v) {
    return String(+v.toPrecision(12));
  }

  CanopyReplay.fragmentOf = function (app) {
    const s = app.state, v = app.view, parts = [];
    parts.push("k=" + s.k);
    parts.push("agent=" + s.agent);
    if (s.selection) parts.push("sel=" + (s.selection.kind === "agent" ? "a" : "t") + s.selection.index);
    parts.push("layers=" + CanopyReplay.LAYERS.filter(function (l) { return s.layers[l.id]; })
      .map(function (l) { return l.id; }).join(","));
    parts.push("view=" + [v.cx, v.cy, v.scale].map(exact).join(","));
    if (s.plot) parts.push("plot=" + encodeURIComponent(s.plot));
    if (s.second) parts.push("second=" + (s.second.on ? 1 : 0));  // an overlay page's second run
    return parts.join("&");
  };

  function whole(text, below) {
    return /^\d+$/.test(text || "") && +text < below ? +text : null;
  }

  // Applies a fragment ("#…" or "…") to the app; what it cannot read is left as it is. Returns
  // the keys it applied.
  CanopyReplay.applyFragment = function (app, fragment) {
    const run = app.run, s = app.state, applied = [], fields = {};
    String(fragment || "").replace(/^#/, "").split("&").forEach(function (part) {
      const at = part.indexOf("=");
      if (at > 0) fields[part.slice(0, at)] = decodeURIComponent(part.slice(at + 1));
    });
    const agent = whole(fields.agent, run.agents.length);
    if (agent !== null) { s.agent = agent; applied.push("agent"); }
    const sel = /^([at])(\d+)$/.exec(fields.sel || "");
    if (sel && +sel[2] < (sel[1] === "a" ? run.agents.length : run.targets.length)) {
      s.selection = { kind: sel[1] === "a" ? "agent" : "target", index: +sel[2] };
      if (s.selection.kind === "agent") s.agent = s.selection.index;
      applied.push("sel");
    }
    if (fields.layers !== undefined) {
      const on = fields.layers.split(",");
      CanopyReplay.LAYERS.forEach(function (l) { s.layers[l.id] = on.indexOf(l.id) >= 0; });
      applied.push("layers");
    }
    const view = (fields.view || "").split(",").map(Number);
    if (view.length === 3 && view.every(isFinite) && view[2] > 0) {
      app.view.cx = view[0];
      app.view.cy = view[1];
      app.view.scale = view[2];
      applied.push("view");
    }
    if (fields.plot) { s.plot = fields.plot; applied.push("plot"); }
    if (s.second && (fields.second === "0" || fields.second === "1")) {
      s.second.on = fields.second === "1";
      applied.push("second");
    }
    const k = whole(fields.k, run.steps);
    if (k !== null) { s.k = k; applied.push("k"); }
    return applied;
  };

  // Writes the fragment a moment after the last change (a browser limits how often a page may
  // rewrite its address; playing changes the step 60 times a second).
  CanopyReplay.noteState = function (app) {
    clearTimeout(app.fragmentTimer);
    app.fragmentTimer = setTimeout(function () {
      try {
        history.replaceState(null, "", "#" + CanopyReplay.fragmentOf(app));
      } catch (e) {
        // A page with no address of its own (a frame of side_by_side.html): nothing to write.
      }
    }, 150);
  };

  CanopyReplay.exportPng = function (app) {
    app.draw();
    return app.view.canvas.toDataURL("image/png");
  };

  // The current view drawn into an SVG document (text).
  CanopyReplay.exportSvg = function (app) {
    const v = app.view, svg = new CanopyReplay.SvgContext(v.width, v.height, v.ratio);
    const backdrop = app.backdrop, vectorBackdrop = {
      draw: function (ctx, view, treesOn) { backdrop.paint(ctx, view, treesOn); }
    };
    CanopyReplay.drawMap(svg, v, app.run, app.state, vectorBackdrop);
    return svg.serialize();
  };

  function fileName(app, extension) {
    return ("canopy_" + app.run.scenario + "_k" + app.state.k).replace(/[^A-Za-z0-9_.-]+/g, "_") + "." + extension;
  }

  // Saves a file through a link with `download` (no request leaves the page).
  function save(name, url) {
    const a = document.createElement("a");
    a.href = url;
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
  }

  CanopyReplay.bindExport = function (app) {
    document.getElementById("export-png").addEventListener("click", function () {
      save(fileName(app, "png"), CanopyReplay.exportPng(app));
    });
    document.getElementById("export-svg").addEventListener("click", function () {
      const url = URL.createObjectURL(new Blob([CanopyReplay.exportSvg(app)], { type: "image/svg+xml" }));
      save(fileName(app, "svg"), url);
      setTimeout(function () { URL.revokeObjectURL(url); }, 1000);
    });
  };
})();
