// The replay page's speed in Debian's headless chromium: first paint, and playing a whole run
// at 60 steps/s with every layer on and a timeline open (mean and worst time to draw a step,
// frame intervals, frames that took longer than 1.5 frame periods, steps per second between the
// first and the last animation frame), and, as a control, as many animation frames on a blank
// page in the same tab (its late frames are the browser's and the machine's).
// Usage: node bench/replay_speed.js CANOPY_BINARY SCENARIO WORK_DIR [REPEATS]
//
// With --step, the time of one step (→) on written pages, opened in one chromium session in
// turn, REPEATS rounds (tests/replay/step_time.js: key press to pixels ready, 30 steps a round,
// every layer on, a person's timeline open); prints each page's size, the median per round and,
// on Linux, the CPU time the renderer's main threads used per step over the 30 steps (from
// /proc: user + system, in 10 ms ticks; less sensitive than the wall time to other programs on
// the machine, and including the page's own painting between the steps):
//   node bench/replay_speed.js --step PAGE.html [PAGE.html ...] [--repeats N]
"use strict";

const fs = require("fs");
const path = require("path");
const { spawnSync } = require("child_process");
const { Browser, Page } = require("../tests/replay/cdp.js");
const { prepare, pressTimes } = require("../tests/replay/step_time.js");

const [canopy, scenario, work, repeatsText] = process.argv.slice(2);
const repeats = +(repeatsText || 3);

// The CPU time (ms) used so far by the main threads of the renderer processes under `pid` (the
// browser), or NaN where /proc cannot tell.
function rendererMainCpuMs(pid) {
  try {
    const stat = (p, file) => {
      const s = fs.readFileSync(`/proc/${p}/${file}`, "utf8");
      return s.slice(s.lastIndexOf(")") + 2).split(" ");  // fields from the state on
    };
    const procs = fs.readdirSync("/proc").filter((d) => /^\d+$/.test(d)).map((d) => {
      try {
        return { pid: +d, ppid: +stat(d, "stat")[1], cmd: fs.readFileSync(`/proc/${d}/cmdline`, "utf8") };
      } catch (e) {
        return null;  // gone meanwhile
      }
    }).filter(Boolean);
    let ticks = 0;
    const stack = [pid];
    while (stack.length) {
      const parent = stack.pop();
      for (const q of procs) {
        if (q.ppid !== parent) continue;
        stack.push(q.pid);
        if (q.cmd.includes("--type=renderer")) {
          const f = stat(q.pid, `task/${q.pid}/stat`);
          ticks += +f[11] + +f[12];  // utime, stime
        }
      }
    }
    return ticks * 10;  // 100 ticks a second (Linux's USER_HZ)
  } catch (e) {
    return NaN;
  }
}

async function stepMain(args) {
  let rounds = 3;
  const pages = [];
  for (let i = 0; i < args.length; i++) {
    if (args[i] === "--repeats") rounds = +args[++i];
    else pages.push(path.resolve(args[i]));
  }
  const browser = new Browser(process.env.CANOPY_CHROMIUM);
  const rows = pages.map((p) => ({ page: p, bytes: fs.statSync(p).size, median_step_ms: [], cpu_ms_per_step: [] }));
  try {
    for (let r = 0; r < rounds; r++) {
      for (const row of rows) {
        const tab = await Page.open(browser, 1280, 900);
        await tab.navigate("file://" + row.page);
        await tab.evaluate("CanopyReplay.ready || null");
        await prepare(tab);
        const cpu0 = rendererMainCpuMs(browser.process.pid);
        const s = await pressTimes(tab, 30);
        const cpu1 = rendererMainCpuMs(browser.process.pid);
        row.median_step_ms.push(+s.median.toFixed(1));
        row.cpu_ms_per_step.push(+((cpu1 - cpu0) / s.times.length).toFixed(2));
        row.backdrop = s.backdrop;
        await tab.send("Page.close").catch(() => {});
      }
    }
  } finally {
    await browser.close();
  }
  rows.forEach((row) => console.log(JSON.stringify(row)));
}

function median(values) {
  const s = values.slice().sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : NaN;
}

async function main() {
  const runDir = path.join(work, "speed_run");
  const made = spawnSync(canopy, ["run", scenario, "--out", runDir, "--html"], { encoding: "utf8" });
  if (made.status !== 0) throw new Error(made.stderr);
  const page = path.resolve(runDir, "replay.html");
  const browser = new Browser(process.env.CANOPY_CHROMIUM);
  const rows = [];
  try {
    for (let r = 0; r < repeats; r++) {
      const tab = await Page.open(browser, 1280, 900);
      const t0 = process.hrtime.bigint();
      await tab.navigate("file://" + page);
      const loadMs = Number(process.hrtime.bigint() - t0) / 1e6;
      const first = await tab.evaluate("({ paint: CanopyReplay.app.stats.firstPaintSinceNavigation, " +
        "script: CanopyReplay.app.stats.firstPaintMs, steps: CanopyReplay.app.run.steps })");
      const play = await tab.evaluate(`new Promise((done) => {
        const app = CanopyReplay.app;
        CanopyReplay.LAYERS.forEach((l) => app.setLayer(l.id, true));
        app.select({ kind: "target", index: 0 });
        app.state.rate = 60;
        app.setStep(0);
        // Press play once the set-up above is on screen (two animation frames later), as a user
        // does: its draws are not part of playing.
        requestAnimationFrame(() => requestAnimationFrame(() => {
          app.stats = { draws: 0, drawMs: 0, drawMsMax: 0, frames: 0, stepsPlayed: 0, frameGaps: [] };
          const start = performance.now();
          app.togglePlay();
          const wait = () => app.state.playing ? setTimeout(wait, 50)
            : done(Object.assign({ wallMs: performance.now() - start }, app.stats));
          wait();
        }));
      })`);
      // The control: the same number of animation frames on a blank page in the same tab, which
      // draws nothing. Frames it gets late are the browser's and the machine's, not the replay's.
      await tab.navigate("about:blank");
      const blank = await tab.evaluate(`new Promise((done) => {
        const gaps = []; let last = null;
        function frame(now) {
          if (last !== null) gaps.push(now - last);
          last = now;
          if (gaps.length < ${play.frameGaps.length}) requestAnimationFrame(frame); else done(gaps);
        }
        requestAnimationFrame(frame);
      })`);
      const gaps = play.frameGaps, period = median(gaps);
      const playedMs = gaps.reduce((a, b) => a + b, 0);  // first to last animation frame
      rows.push({
        load_ms: +loadMs.toFixed(1), first_paint_ms: +first.paint.toFixed(1),
        script_to_paint_ms: +first.script.toFixed(1), steps: first.steps,
        steps_played: play.stepsPlayed, wall_s: +(play.wallMs / 1000).toFixed(3),
        steps_per_s: +(play.stepsPlayed / (playedMs / 1000)).toFixed(1),
        draws: play.draws, mean_draw_ms: +(play.drawMs / play.draws).toFixed(3),
        max_draw_ms: +play.drawMsMax.toFixed(2), frames: play.frames,
        median_frame_ms: +period.toFixed(2), max_frame_ms: +Math.max.apply(null, gaps).toFixed(2),
        late_frames: gaps.filter((g) => g > 1.5 * period).length,
        late_frame_at: gaps.map((g, i) => (g > 1.5 * period ? i : -1)).filter((i) => i >= 0),
        blank_page_late_frames: blank.filter((g) => g > 1.5 * median(blank)).length,
        blank_page_max_frame_ms: +Math.max.apply(null, blank).toFixed(2),
        steps_not_drawn: play.stepsPlayed - play.draws
      });
      await tab.send("Page.close").catch(() => {});
    }
  } finally {
    await browser.close();
  }
  rows.forEach((row) => console.log(JSON.stringify(row)));
}

(process.argv[2] === "--step" ? stepMain(process.argv.slice(3)) : main())
  .catch((e) => { console.error(e); process.exit(1); });
