// A drawing context with the part of the canvas 2D API the map's layers use, which writes SVG
// elements instead of pixels: the export of the view as SVG runs the same drawing code as the
// screen. Paths, fills, strokes, dashes, clips, rectangles and text become SVG shapes and text;
// an image drawn (the trees' density raster) becomes an <image>. Transforms are scale and
// translation (the layers turn nothing when `vector` is set; symbols.js). Coordinates are the
// canvas's CSS pixels: `ratio` device pixels per CSS pixel, as the layers set with setTransform.
/* global CanopyReplay */
(function () {
  "use strict";

  const NS = "http://www.w3.org/2000/svg";

  function num(v) {
    return String(Math.round(v * 100) / 100);
  }

  // "rgba(r,g,b,a)" → ["rgb(r,g,b)", a]; any other colour as it is, opacity 1.
  function paint(colour) {
    const m = /^rgba\(\s*([\d.]+)\s*,\s*([\d.]+)\s*,\s*([\d.]+)\s*,\s*([\d.]+)\s*\)$/.exec(String(colour));
    return m ? ["rgb(" + m[1] + "," + m[2] + "," + m[3] + ")", +m[4]] : [String(colour), 1];
  }

  function SvgContext(width, height, ratio) {
    this.vector = true;  // the layers draw shapes, not sprites
    this.ratio = ratio;
    this.root = document.createElementNS(NS, "svg");
    this.root.setAttribute("xmlns", NS);
    this.root.setAttribute("width", String(width));
    this.root.setAttribute("height", String(height));
    this.root.setAttribute("viewBox", "0 0 " + width + " " + height);
    this.defs = document.createElementNS(NS, "defs");
    this.root.appendChild(this.defs);
    this.parent = this.root;
    this.clips = 0;
    this.m = [1, 0, 0, 1, 0, 0];
    this.d = [];          // the current path's commands
    this.current = null;  // the current point (output px), or null
    this.dash = [];
    this.fillStyle = "#000";
    this.strokeStyle = "#000";
    this.lineWidth = 1;
    this.lineJoin = "miter";
    this.lineCap = "butt";
    this.font = "10px sans-serif";
    this.textAlign = "start";
    this.stack = [];
    this.measure = document.createElement("canvas").getContext("2d");
  }

  const STATE = ["m", "dash", "fillStyle", "strokeStyle", "lineWidth", "lineJoin", "lineCap", "font", "textAlign", "parent"];

  SvgContext.prototype.save = function () {
    const self = this, saved = {};
    STATE.forEach(function (key) { saved[key] = self[key]; });
    this.stack.push(saved);
  };
  SvgContext.prototype.restore = function () {
    const saved = this.stack.pop(), self = this;
    if (saved) STATE.forEach(function (key) { self[key] = saved[key]; });
  };
  SvgContext.prototype.setTransform = function (a, b, c, d, e, f) { this.m = [a, b, c, d, e, f]; };
  SvgContext.prototype.setLineDash = function (dash) { this.dash = dash.slice(); };
  SvgContext.prototype.getLineDash = function () { return this.dash.slice(); };

  // A point in the layers' coordinates → output px.
  SvgContext.prototype.point = function (x, y) {
    const m = this.m, r = this.ratio;
    return [(m[0] * x + m[2] * y + m[4]) / r, (m[1] * x + m[3] * y + m[5]) / r];
  };
  SvgContext.prototype.scale = function () {
    return Math.sqrt(Math.abs(this.m[0] * this.m[3] - this.m[1] * this.m[2])) / this.ratio;
  };

  SvgContext.prototype.beginPath = function () { this.d = []; this.current = null; };
  SvgContext.prototype.moveTo = function (x, y) {
    const p = this.point(x, y);
    this.d.push("M" + num(p[0]) + " " + num(p[1]));
    this.current = p;
  };
  SvgContext.prototype.lineTo = function (x, y) {
    const p = this.point(x, y);
    this.d.push((this.current ? "L" : "M") + num(p[0]) + " " + num(p[1]));
    this.current = p;
  };
  SvgContext.prototype.closePath = function () { if (this.d.length) this.d.push("Z"); };

  // An elliptic arc of the ellipse at c with half-axes rx, ry turned by `turn` (rad, clockwise on
  // the screen) from angle a0 to a1 (ccw: the other way), as the canvas's arc() and ellipse():
  // a line from the current point to its start, then at most two SVG arcs.
  SvgContext.prototype.arcPath = function (cx, cy, rx, ry, turn, a0, a1, ccw) {
    let sweep = ccw ? a0 - a1 : a1 - a0;
    const full = sweep >= 2 * Math.PI;
    sweep = full ? 2 * Math.PI : ((sweep % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
    const s = this.scale(), c = this.point(cx, cy), cos = Math.cos(turn), sin = Math.sin(turn);
    const at = function (a) {
      const u = rx * Math.cos(a) * s, v = ry * Math.sin(a) * s;
      return [c[0] + cos * u - sin * v, c[1] + sin * u + cos * v];
    };
    const start = at(a0), dir = ccw ? -1 : 1, flag = ccw ? "0" : "1";
    this.d.push((this.current ? "L" : "M") + num(start[0]) + " " + num(start[1]));
    const head = "A" + num(rx * s) + " " + num(ry * s) + " " + num(turn * 180 / Math.PI) + " ";
    const half = sweep / 2, mid = at(a0 + dir * half), end = at(a0 + dir * sweep);
    this.d.push(head + "0 " + flag + " " + num(mid[0]) + " " + num(mid[1]));
    this.d.push(head + "0 " + flag + " " + num(end[0]) + " " + num(end[1]));
    this.current = end;
  };
  SvgContext.prototype.arc = function (x, y, r, a0, a1, ccw) {
    this.arcPath(x, y, r, r, 0, a0, a1, !!ccw);
  };
  SvgContext.prototype.ellipse = function (x, y, rx, ry, turn, a0, a1, ccw) {
    this.arcPath(x, y, rx, ry, turn, a0, a1, !!ccw);
  };

  SvgContext.prototype.add = function (tag, attributes) {
    const e = document.createElementNS(NS, tag);
    Object.keys(attributes).forEach(function (key) { e.setAttribute(key, attributes[key]); });
    this.parent.appendChild(e);
    return e;
  };
  SvgContext.prototype.strokeAttributes = function (a) {
    const p = paint(this.strokeStyle), s = this.scale();
    a.fill = "none";
    a.stroke = p[0];
    if (p[1] !== 1) a["stroke-opacity"] = String(p[1]);
    a["stroke-width"] = num(this.lineWidth * s);
    if (this.lineJoin !== "miter") a["stroke-linejoin"] = this.lineJoin;
    if (this.lineCap !== "butt") a["stroke-linecap"] = this.lineCap;
    if (this.dash.length) a["stroke-dasharray"] = this.dash.map(function (v) { return num(v * s); }).join(" ");
    return a;
  };
  SvgContext.prototype.fillAttributes = function (a) {
    const p = paint(this.fillStyle);
    a.fill = p[0];
    if (p[1] !== 1) a["fill-opacity"] = String(p[1]);
    return a;
  };
  SvgContext.prototype.fill = function (rule) {
    if (!this.d.length) return;
    const a = this.fillAttributes({ d: this.d.join("") });
    if (rule === "evenodd") a["fill-rule"] = "evenodd";
    this.add("path", a);
  };
  SvgContext.prototype.stroke = function () {
    if (this.d.length) this.add("path", this.strokeAttributes({ d: this.d.join("") }));
  };
  // Later elements are drawn inside the current path, until restore().
  SvgContext.prototype.clip = function () {
    const id = "clip" + (++this.clips), clip = document.createElementNS(NS, "clipPath");
    clip.setAttribute("id", id);
    const path = document.createElementNS(NS, "path");
    path.setAttribute("d", this.d.join("") || "M0 0");
    clip.appendChild(path);
    this.defs.appendChild(clip);
    this.parent = this.add("g", { "clip-path": "url(#" + id + ")" });
  };
  SvgContext.prototype.rect = function (x, y, w, h) {
    const a = this.point(x, y), b = this.point(x + w, y + h);
    return { x: num(Math.min(a[0], b[0])), y: num(Math.min(a[1], b[1])),
      width: num(Math.abs(b[0] - a[0])), height: num(Math.abs(b[1] - a[1])) };
  };
  SvgContext.prototype.fillRect = function (x, y, w, h) { this.add("rect", this.fillAttributes(this.rect(x, y, w, h))); };
  SvgContext.prototype.strokeRect = function (x, y, w, h) { this.add("rect", this.strokeAttributes(this.rect(x, y, w, h))); };

  SvgContext.prototype.text = function (text, x, y, attributes) {
    const p = this.point(x, y), s = this.scale();
    attributes.x = num(p[0]);
    attributes.y = num(p[1]);
    attributes.style = "font: " + this.font.replace(/(\d+(\.\d+)?)px/, function (all, size) { return num(size * s) + "px"; });
    if (this.textAlign === "center") attributes["text-anchor"] = "middle";
    if (this.textAlign === "right" || this.textAlign === "end") attributes["text-anchor"] = "end";
    this.add("text", attributes).textContent = text;
  };
  SvgContext.prototype.fillText = function (text, x, y) { this.text(text, x, y, this.fillAttributes({})); };
  SvgContext.prototype.strokeText = function (text, x, y) { this.text(text, x, y, this.strokeAttributes({})); };
  SvgContext.prototype.measureText = function (text) {
    this.measure.font = this.font;
    return this.measure.measureText(text);
  };

  // An image (a canvas) placed as the canvas's drawImage places it, embedded as a PNG.
  SvgContext.prototype.drawImage = function (image, dx, dy, dw, dh) {
    const w = dw === undefined ? image.width : dw, h = dh === undefined ? image.height : dh;
    const a = this.rect(dx, dy, w, h);
    a.href = image.toDataURL("image/png");
    a.preserveAspectRatio = "none";
    this.add("image", a);
  };

  // The drawing as an SVG document.
  SvgContext.prototype.serialize = function () {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + new XMLSerializer().serializeToString(this.root) + "\n";
  };

  CanopyReplay.SvgContext = SvgContext;
})();
