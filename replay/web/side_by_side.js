// Two replay pages side by side (each in an iframe of its own, written whole into `srcdoc`) on
// one clock: moving either page's step, or the slider above them, sets the other page to the step
// of the same time (k = round(t / dt), clamped to its run). Their views are linked (while "link
// the views" is ticked): both open on the box of both runs, and a pan or zoom in one moves the
// other to the same centre and scale. The address's fragment (#t=SECONDS&view=CX,CY,SCALE) holds
// the time and the left page's view, and opening it restores them. One play button plays both in
// real time. The layers, the shown agent's beliefs, the selection and the plotted field set in
// either page are set in the other too. CanopySideBySide is what the browser tests drive and read.
(function () {
  "use strict";

  const frames = [document.getElementById("run-a"), document.getElementById("run-b")];
  const slider = document.getElementById("clock-slider"), clock = document.getElementById("clock");
  const link = document.getElementById("link-views");
  const side = { apps: [], time: 0 };
  window.CanopySideBySide = side;

  // Resolves with the frame's page once it has drawn its first step.
  function readyOf(frame) {
    return new Promise(function (resolve) {
      function poll() {
        const replay = frame.contentWindow && frame.contentWindow.CanopyReplay;
        if (replay && replay.ready) replay.ready.then(function () { resolve(replay.app); });
        else setTimeout(poll, 20);
      }
      poll();
    });
  }

  let syncing = false;
  // Sets every page (but `from`, which is there already) to the step of time t (s).
  side.setTime = function (t, from) {
    if (syncing) return;
    syncing = true;
    side.time = t;
    side.apps.forEach(function (app, n) {
      if (n !== from) app.setStep(Math.round(t / app.run.dt));
    });
    slider.value = String(t);
    clock.textContent = "t = " + t.toFixed(2) + " s";
    syncing = false;
    noteState();
  };

  // Writes the fragment a moment after the last change (as share.js does for one page).
  let timer = null;
  function noteState() {
    clearTimeout(timer);
    timer = setTimeout(function () {
      if (!side.apps.length) return;
      const v = side.apps[0].view;
      history.replaceState(null, "", "#t=" + String(+side.time.toPrecision(12)) + "&view=" +
        [v.cx, v.cy, v.scale].map(function (x) { return String(+x.toPrecision(12)); }).join(","));
    }, 150);
  }

  // The time and view of a fragment, where it holds them.
  function applyFragment(apps) {
    const fields = {};
    location.hash.replace(/^#/, "").split("&").forEach(function (part) {
      const at = part.indexOf("=");
      if (at > 0) fields[part.slice(0, at)] = part.slice(at + 1);
    });
    const view = (fields.view || "").split(",").map(Number);
    if (view.length === 3 && view.every(isFinite) && view[2] > 0) {
      apps[0].view.cx = view[0];
      apps[0].view.cy = view[1];
      apps[0].view.scale = view[2];
      apps[0].draw();
    }
    const t = Number(fields.t);
    if (fields.t !== undefined && isFinite(t) && t >= 0) side.setTime(t);
  }

  // One play button for both: each animation frame moves the clock on by the time elapsed
  // (real time), and both pages to their steps of that time, until the longer run ends.
  const play = document.getElementById("play-both");
  side.playing = false;
  side.togglePlay = function () {
    side.playing = !side.playing;
    play.textContent = side.playing ? "\u23f8 pause" : "\u25b6 play";
    if (!side.playing) return;
    if (side.time >= side.end) side.setTime(0);
    let last = null;
    function frame(now) {
      if (!side.playing) return;
      if (last !== null) side.setTime(Math.min(side.end, side.time + (now - last) / 1000));
      last = now;
      if (side.time >= side.end) return side.togglePlay();
      requestAnimationFrame(frame);
    }
    requestAnimationFrame(frame);
  };

  let linking = false;
  // Moves every page's view but `from`'s to the centre and scale of `from`'s.
  side.linkViews = function (from) {
    if (linking || !link.checked) return;
    linking = true;
    const v = from.view;
    side.apps.forEach(function (app) {
      if (app === from || (app.view.cx === v.cx && app.view.cy === v.cy && app.view.scale === v.scale)) return;
      app.view.cx = v.cx;
      app.view.cy = v.cy;
      app.view.scale = v.scale;
      app.draw();
    });
    linking = false;
  };

  // What one page's user changes that the other page follows: the layers, the agent whose
  // beliefs are shown, the selection and the plotted field; an agent or a person by its
  // counterpart in the other run (the same name, else the same place: compare.js).
  let mirroring = false;
  function mirror(apps) {
    const replays = frames.map(function (frame) { return frame.contentWindow.CanopyReplay; });
    const follow = {
      setLayer: function (from, to, args) { return [args[0], args[1]]; },
      setPlot: function (from, to, args) { return [args[0]]; },
      setAgent: function (from, to, args) {
        const i = replays[to].counterpartAgent(apps[from].run, apps[to].run, args[0]);
        return i >= 0 ? [i] : null;
      },
      select: function (from, to, args) {
        const selection = replays[to].counterpart(apps[from].run, apps[to].run, args[0]);
        return selection ? [selection] : null;
      }
    };
    Object.keys(follow).forEach(function (name) {
      apps.forEach(function (app, n) {
        const own = app[name].bind(app);
        app[name] = function () {
          const given = arguments;
          own.apply(null, given);
          if (mirroring) return;
          mirroring = true;
          try {
            apps.forEach(function (other, m) {
              const args = m === n ? null : follow[name](n, m, given);
              if (args) other[name].apply(other, args);
            });
          } finally {
            mirroring = false;
          }
        };
      });
    });
    // Each page's legend says which run it shows and which is beside it.
    apps.forEach(function (app, n) { replays[n].markRuns(app, apps[1 - n].run); });
  }

  side.ready = Promise.all(frames.map(readyOf)).then(function (apps) {
    side.apps = apps;
    mirror(apps);
    // Both pages open on the box that holds both runs.
    const box = apps.map(function (app) { return app.box; }).reduce(function (a, b) {
      return [Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[2], b[2]), Math.max(a[3], b[3])];
    });
    apps.forEach(function (app) {
      app.box = box;
      const ownDraw = app.draw.bind(app);
      app.draw = function () {
        ownDraw();
        side.linkViews(app);
        noteState();
      };
    });
    apps[0].fit();
    link.addEventListener("change", function () { side.linkViews(apps[0]); });
    apps.forEach(function (app, n) {
      const own = app.setStep.bind(app);
      app.setStep = function (k) {
        own(k);
        side.setTime(app.run.time(app.state.k), n);
      };
    });
    const end = Math.max.apply(null, apps.map(function (app) { return app.run.time(app.run.steps - 1); }));
    side.end = end;
    slider.max = String(end);
    play.addEventListener("click", function () { side.togglePlay(); });
    slider.addEventListener("input", function () { side.setTime(+slider.value); });
    side.setTime(0);
    applyFragment(apps);
  });
})();
