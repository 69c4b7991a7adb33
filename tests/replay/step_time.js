// How long one step (→) takes on an open replay page: from the key press to the map's pixels
// being ready (a one-pixel read of the canvas waits for its drawing to finish), one animation
// frame between presses, every layer on and the first person's timeline open, from a third of
// the run on. Used by the browser test and bench/replay_speed.js --step.
"use strict";

// Every layer on, person 0's timeline open, at step ⌊steps / 3⌋; resolves to that step.
async function prepare(page) {
  return page.evaluate(`(() => {
    const app = CanopyReplay.app;
    CanopyReplay.LAYERS.forEach((l) => app.setLayer(l.id, true));
    if (app.run.targets.length) app.select({ kind: "target", index: 0 });
    app.setStep(Math.floor(app.run.steps / 3));
    app.ctx.getImageData(0, 0, 1, 1);
    return app.state.k;
  })()`);
}

// Presses → `count` times (fewer at the run's end) on a prepared page; resolves to
// {times: [ms per step], median, k: the step reached, backdrop: the backdrop's stats after}.
async function pressTimes(page, count) {
  return page.evaluate(`new Promise((done) => {
    const app = CanopyReplay.app, ctx = app.ctx, times = [];
    function press() {
      const t0 = performance.now();
      document.dispatchEvent(new KeyboardEvent("keydown", { key: "ArrowRight", code: "ArrowRight", bubbles: true }));
      ctx.getImageData(0, 0, 1, 1);
      times.push(performance.now() - t0);
      if (times.length < ${count} && app.state.k < app.run.steps - 1) requestAnimationFrame(press);
      else {
        const sorted = times.slice().sort((a, b) => a - b);
        done({ times: times, median: sorted[Math.floor(sorted.length / 2)], k: app.state.k,
          backdrop: app.backdrop ? Object.assign({}, app.backdrop.stats) : null });
      }
    }
    requestAnimationFrame(press);
  })`);
}

// Resolves to {times, median, k0, k, backdrop}.
async function stepTimes(page, count) {
  const k0 = await prepare(page);
  return Object.assign({ k0 }, await pressTimes(page, count));
}

module.exports = { stepTimes, prepare, pressTimes };
