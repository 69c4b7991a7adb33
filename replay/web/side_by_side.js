// Two replay pages side by side (each in an iframe of its own, written whole into `srcdoc`) on
// one clock: moving either page's step, or the slider above them, sets the other page to the step
// of the same time (k = round(t / dt), clamped to its run). CanopySideBySide is what the browser
// tests drive and read.
(function () {
  "use strict";

  const frames = [document.getElementById("run-a"), document.getElementById("run-b")];
  const slider = document.getElementById("clock-slider"), clock = document.getElementById("clock");
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
  };

  side.ready = Promise.all(frames.map(readyOf)).then(function (apps) {
    side.apps = apps;
    apps.forEach(function (app, n) {
      const own = app.setStep.bind(app);
      app.setStep = function (k) {
        own(k);
        side.setTime(app.run.time(app.state.k), n);
      };
    });
    const end = Math.max.apply(null, apps.map(function (app) { return app.run.time(app.run.steps - 1); }));
    slider.max = String(end);
    slider.addEventListener("input", function () { side.setTime(+slider.value); });
    side.setTime(0);
  });
})();
