// What the browser tests share: a named check that reports ok / not ok and carries on, asserts,
// running canopy, the map's pixels, and the end (exit 0 when every check passed, 1 otherwise).
"use strict";

const { spawnSync } = require("child_process");

const results = [];
let canopyBinary = null;

function setCanopy(binary) { canopyBinary = binary; }

// The chromium to drive ($CANOPY_CHROMIUM or Debian's); without it the test is skipped (exit 77,
// ctest's skip code).
function chromiumOrSkip() {
  const chromium = process.env.CANOPY_CHROMIUM || "/usr/bin/chromium";
  if (!require("fs").existsSync(chromium)) {
    console.log("SKIP: " + chromium + " is missing (Debian package chromium; ./canopy installs it)");
    process.exit(77);
  }
  return chromium;
}

async function check(name, body) {
  try {
    await body();
    results.push(name);
    console.log("ok - " + name);
  } catch (e) {
    results.push(null);
    console.log("not ok - " + name + "\n    " + String(e && e.stack || e).split("\n").join("\n    "));
  }
}

function assert(condition, message) {
  if (!condition) throw new Error(message);
}

function canopyRun(args) {
  const r = spawnSync(canopyBinary, args, { encoding: "utf8" });
  if (r.status !== 0) throw new Error("canopy " + args.join(" ") + ": " + r.stderr);
  return r;
}

// The pixels (RGBA) of a canvas of the page (the map unless `expression` names another) as a
// Buffer, with its width and height.
async function mapPixels(page, expression) {
  const r = await page.evaluate(`(() => {
    const c = ${expression || 'document.getElementById("map")'}, d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    let s = "";
    for (let i = 0; i < d.length; i += 0x8000) s += String.fromCharCode.apply(null, d.subarray(i, i + 0x8000));
    return { w: c.width, h: c.height, data: btoa(s) };
  })()`);
  return { w: r.w, h: r.h, data: Buffer.from(r.data, "base64") };
}

function finish() {
  const failed = results.filter((r) => r === null).length;
  console.log(`${results.length - failed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}

function crashed(e) {
  console.log("not ok - the harness itself: " + (e && e.stack || e));
  console.log("0 passed, 1 failed");
  process.exit(1);
}

module.exports = { setCanopy, chromiumOrSkip, check, assert, canopyRun, mapPixels, finish, crashed };
