// How long one step (→) takes on an open replay page: from the key press to the map's pixels
// being ready (a one-pixel read of the canvas waits for its drawing to finish), one animation
// frame between presses, every layer on and the first person's timeline open, from a third of
// the run on. Used by the browser test and bench/replay_speed.js --step.
"use strict";

// Resolves to {times: [ms per step], median, k0, backdrop: the backdrop's stats after}.
async function stepTimes(page, count) {
  return page.evaluate(`new Promise((done) => {
    const app = CanopyReplay.app, ctx = app.ctx, times = [];
    CanopyReplay.LAYERS.forEach((l) => app.setLayer(l.id, true));
    if (app.run.targets.length) app.select({ kind: "target", index: 0 });
    const k0 = Math.floor(app.run.steps / 3);
    app.setStep(k0);
    ctx.getImageData(0, 0, 1, 1);
    function press() {
      const t0 = performance.now();
      document.dispatchEvent(new KeyboardEvent("keydown", { key: "ArrowRight", code: "ArrowRight", bubbles: true }));
      ctx.getImageData(0, 0, 1, 1);
      times.push(performance.now() - t0);
      if (times.length < ${count} && app.state.k < app.run.steps - 1) requestAnimationFrame(press);
      else {
        const sorted = times.slice().sort((a, b) => a - b);
        done({ times: times, median: sorted[Math.floor(sorted.length / 2)], k0: k0, k: app.state.k,
          backdrop: app.backdrop ? Object.assign({}, app.backdrop.stats) : null });
      }
    }
    requestAnimationFrame(press);
  })`);
}

module.exports = { stepTimes };
