// A small client of the Chrome DevTools protocol over a pipe (chromium --remote-debugging-pipe:
// commands on its fd 3, replies and events on its fd 4, each a JSON text ended by a NUL byte),
// so that the browser tests need nothing but node and Debian's chromium: no network port, no
// package download.
"use strict";

const { spawn } = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");

class Browser {
  // Starts headless chromium with a fresh profile; `executable` defaults to /usr/bin/chromium.
  constructor(executable) {
    this.profile = fs.mkdtempSync(path.join(os.tmpdir(), "canopy-chromium-"));
    this.process = spawn(executable || "/usr/bin/chromium", [
      "--headless=new", "--remote-debugging-pipe", "--no-sandbox", "--disable-gpu",
      "--no-first-run", "--no-default-browser-check", "--disable-extensions",
      "--disable-background-networking", "--disable-component-update", "--disable-sync",
      "--user-data-dir=" + this.profile, "about:blank"
    ], { stdio: ["ignore", "ignore", "pipe", "pipe", "pipe"] });
    this.stderr = "";
    this.process.stderr.on("data", (d) => { this.stderr += d; });
    this.nextId = 1;
    this.pending = new Map();
    this.listeners = [];
    let buffer = Buffer.alloc(0);
    this.process.stdio[4].on("data", (chunk) => {
      buffer = Buffer.concat([buffer, chunk]);
      let end;
      while ((end = buffer.indexOf(0)) >= 0) {
        const message = JSON.parse(buffer.subarray(0, end).toString("utf8"));
        buffer = buffer.subarray(end + 1);
        this.dispatch(message);
      }
    });
    this.exited = new Promise((resolve) => this.process.on("exit", resolve));
  }

  dispatch(message) {
    if (message.id !== undefined && this.pending.has(message.id)) {
      const { resolve, reject, method } = this.pending.get(message.id);
      this.pending.delete(message.id);
      if (message.error) reject(new Error(method + ": " + message.error.message));
      else resolve(message.result);
      return;
    }
    this.listeners.forEach((listener) => listener(message));
  }

  // Sends a command (to a page when sessionId is given) and resolves with its result.
  send(method, params, sessionId) {
    const id = this.nextId++;
    const message = { id, method, params: params || {} };
    if (sessionId) message.sessionId = sessionId;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject, method });
      this.process.stdio[3].write(JSON.stringify(message) + "\0");
    });
  }

  on(listener) { this.listeners.push(listener); }

  // Resolves with the first event named `method` (of `sessionId`) for which `test` holds.
  waitFor(method, sessionId, test, timeoutMs) {
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error("timed out waiting for " + method)),
        timeoutMs || 30000);
      const listener = (m) => {
        if (m.method !== method || (sessionId && m.sessionId !== sessionId)) return;
        if (test && !test(m.params)) return;
        clearTimeout(timer);
        this.listeners = this.listeners.filter((l) => l !== listener);
        resolve(m.params);
      };
      this.on(listener);
    });
  }

  async close() {
    try { await this.send("Browser.close"); } catch (e) { this.process.kill(); }
    await this.exited;
    fs.rmSync(this.profile, { recursive: true, force: true });
  }
}

// One tab: console errors, exceptions, failed and outside requests are collected from the start.
class Page {
  static async open(browser, width, height) {
    const { targetId } = await browser.send("Target.createTarget", { url: "about:blank" });
    const { sessionId } = await browser.send("Target.attachToTarget", { targetId, flatten: true });
    const page = new Page(browser, sessionId);
    await Promise.all(["Runtime.enable", "Log.enable", "Network.enable", "Page.enable"]
      .map((m) => page.send(m)));
    await page.send("Emulation.setDeviceMetricsOverride",
      { width, height, deviceScaleFactor: 1, mobile: false });
    return page;
  }

  constructor(browser, sessionId) {
    this.browser = browser;
    this.sessionId = sessionId;
    this.errors = [];    // console errors, uncaught exceptions, log errors
    this.requests = [];  // every URL the page asked for
    this.failed = [];    // requests that failed
    browser.on((m) => {
      if (m.sessionId !== sessionId) return;
      const p = m.params;
      if (m.method === "Runtime.exceptionThrown") {
        this.errors.push("exception: " + JSON.stringify(p.exceptionDetails));
      } else if (m.method === "Runtime.consoleAPICalled" && (p.type === "error" || p.type === "assert")) {
        this.errors.push("console." + p.type + ": " + JSON.stringify(p.args));
      } else if (m.method === "Log.entryAdded" && p.entry.level === "error") {
        this.errors.push("log: " + p.entry.text + " " + (p.entry.url || ""));
      } else if (m.method === "Network.requestWillBeSent") {
        this.requests.push(p.request.url);
      } else if (m.method === "Network.loadingFailed") {
        this.failed.push(p.errorText + " " + p.requestId);
      }
    });
  }

  send(method, params) { return this.browser.send(method, params, this.sessionId); }

  async navigate(url) {
    const loaded = this.browser.waitFor("Page.loadEventFired", this.sessionId);
    await this.send("Page.navigate", { url });
    await loaded;
    // A replay page inflates its data after the load event: wait until it has drawn.
    await this.evaluate("typeof CanopyReplay === 'object' && CanopyReplay.ready ? CanopyReplay.ready.then(() => true) : true");
  }

  // The value of a JavaScript expression in the page (awaited when it is a promise).
  async evaluate(expression) {
    const r = await this.send("Runtime.evaluate",
      { expression, returnByValue: true, awaitPromise: true });
    if (r.exceptionDetails) throw new Error("in the page: " + JSON.stringify(r.exceptionDetails));
    return r.result.value;
  }

  async key(key, code, keyCode, shift) {
    const base = { key, code, windowsVirtualKeyCode: keyCode, modifiers: shift ? 8 : 0 };
    await this.send("Input.dispatchKeyEvent", Object.assign({ type: "rawKeyDown" }, base));
    await this.send("Input.dispatchKeyEvent", Object.assign({ type: "keyUp" }, base));
  }

  async click(x, y) {
    const at = { x, y, button: "left", clickCount: 1 };
    await this.send("Input.dispatchMouseEvent", Object.assign({ type: "mouseMoved" }, at));
    await this.send("Input.dispatchMouseEvent", Object.assign({ type: "mousePressed" }, at));
    await this.send("Input.dispatchMouseEvent", Object.assign({ type: "mouseReleased" }, at));
  }

  async wheel(x, y, deltaY) {
    await this.send("Input.dispatchMouseEvent", { type: "mouseWheel", x, y, deltaX: 0, deltaY });
  }

  async drag(x0, y0, x1, y1) {
    await this.send("Input.dispatchMouseEvent", { type: "mouseMoved", x: x0, y: y0 });
    await this.send("Input.dispatchMouseEvent",
      { type: "mousePressed", x: x0, y: y0, button: "left", buttons: 1, clickCount: 1 });
    for (let i = 1; i <= 4; i++) {
      await this.send("Input.dispatchMouseEvent", { type: "mouseMoved", x: x0 + (x1 - x0) * i / 4,
        y: y0 + (y1 - y0) * i / 4, button: "left", buttons: 1 });
    }
    await this.send("Input.dispatchMouseEvent",
      { type: "mouseReleased", x: x1, y: y1, button: "left", buttons: 0, clickCount: 1 });
  }

  async screenshot() {
    const { data } = await this.send("Page.captureScreenshot", { format: "png" });
    return Buffer.from(data, "base64");
  }
}

module.exports = { Browser, Page };
