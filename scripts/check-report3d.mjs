// Drive headless Chromium over the DevTools protocol (through a pipe: no port, no WebSocket, no
// npm package) to check a 3D report (crates/voussoir-io/src/report3d.rs):
//   1. the page loads with no console error and no uncaught exception, and the viewer ran
//      (<body data-ready="1">; "nogl" means WebGL is missing and fails the check);
//   2. the WebGL canvas is drawn: enough of its pixels differ from the background colour;
//   3. a simulated mouse drag (Input.dispatchMouseEvent: press, moves, release) changes the
//      picture, and so does the test hook window.__voussoirRotate(dx, dy);
//   4. the displacement-scale slider and the crack/force checkboxes change the picture.
// Screenshots of the canvas are written as OUTDIR/NAME-1-initial.png, -2-dragged.png,
// -3-hook.png. Usage: node check-report3d.mjs CHROMIUM REPORT.html OUTDIR NAME
import { spawn } from "node:child_process";
import { writeFileSync, mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";

const [chrome, report, outdir, name] = process.argv.slice(2);
if (!chrome || !report || !outdir || !name) {
  console.error("usage: node check-report3d.mjs CHROMIUM REPORT.html OUTDIR NAME");
  process.exit(2);
}
const profile = mkdtempSync(join(tmpdir(), "v3chrome-"));
const proc = spawn(chrome, [
  "--headless", "--no-sandbox", "--remote-debugging-pipe", "--user-data-dir=" + profile,
  "--disable-background-networking", "--disable-component-update", "--disable-sync",
  "--no-first-run", "--hide-scrollbars", "--disable-quic",
  // WebGL without a GPU: ANGLE on SwiftShader (software).
  "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
  "about:blank",
], { stdio: ["ignore", "ignore", "pipe", "pipe", "pipe"] });
let stderr = "";
proc.stdio[2].on("data", (d) => { stderr += d; });

const pending = new Map();
const listeners = [];
let nextId = 1;
let buf = Buffer.alloc(0);
proc.stdio[4].on("data", (chunk) => {
  buf = Buffer.concat([buf, chunk]);
  let i;
  while ((i = buf.indexOf(0)) >= 0) {
    const msg = JSON.parse(buf.subarray(0, i).toString("utf8"));
    buf = buf.subarray(i + 1);
    if (msg.id && pending.has(msg.id)) {
      const { ok, fail } = pending.get(msg.id);
      pending.delete(msg.id);
      if (msg.error) { fail(new Error(JSON.stringify(msg.error))); } else { ok(msg.result); }
    } else if (msg.method) {
      listeners.forEach((l) => l(msg));
    }
  }
});
function send(method, params = {}, sessionId) {
  const id = nextId++;
  const m = { id, method, params };
  if (sessionId) { m.sessionId = sessionId; }
  proc.stdio[3].write(JSON.stringify(m) + "\0");
  return new Promise((ok, fail) => {
    pending.set(id, { ok, fail });
    setTimeout(() => fail(new Error("timeout: " + method)), 60000);
  });
}
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const problems = [];
function finish(code, text) {
  (code === 0 ? console.log : console.error)(text);
  const done = () => {
    try { rmSync(profile, { recursive: true, force: true }); } catch (e) { /* best effort */ }
    process.exit(code);
  };
  if (proc.exitCode !== null) { done(); return; }
  proc.once("exit", done);
  try { proc.kill(); } catch (e) { done(); }
  setTimeout(done, 5000);
}
const timer = setTimeout(() => finish(1, "error: timed out\n" + stderr.slice(-2000)), 170000);

try {
  const { targetId } = await send("Target.createTarget", { url: "about:blank" });
  const { sessionId: s } = await send("Target.attachToTarget", { targetId, flatten: true });
  listeners.push((m) => {
    if (m.sessionId !== s) { return; }
    if (m.method === "Runtime.exceptionThrown") {
      problems.push("uncaught: " + JSON.stringify(m.params.exceptionDetails.exception?.description || m.params.exceptionDetails.text));
    } else if (m.method === "Runtime.consoleAPICalled" && (m.params.type === "error" || m.params.type === "assert")) {
      problems.push("console." + m.params.type + ": " + m.params.args.map((a) => a.value ?? a.description).join(" "));
    } else if (m.method === "Log.entryAdded" && m.params.entry.level === "error") {
      problems.push("log: " + m.params.entry.text + (m.params.entry.url ? " (" + m.params.entry.url + ")" : ""));
    } else if (m.method === "Network.requestWillBeSent") {
      const u = m.params.request.url;
      if (!u.startsWith("file:") && !u.startsWith("data:") && !u.startsWith("about:")) { problems.push("network request: " + u); }
    }
  });
  for (const d of ["Runtime.enable", "Log.enable", "Page.enable", "Network.enable"]) { await send(d, {}, s); }
  await send("Emulation.setDeviceMetricsOverride", { width: 1100, height: 1000, deviceScaleFactor: 1, mobile: false }, s);
  await send("Page.navigate", { url: "file://" + resolve(report) }, s);
  const ev = async (expr) => {
    const r = await send("Runtime.evaluate", { expression: expr, awaitPromise: true, returnByValue: true }, s);
    if (r.exceptionDetails) { throw new Error("evaluate: " + JSON.stringify(r.exceptionDetails)); }
    return r.result.value;
  };
  let ready = null;
  for (let k = 0; k < 200 && !ready; k++) {
    await sleep(100);
    ready = await ev("document.body && document.body.getAttribute('data-ready')").catch(() => null);
  }
  if (ready !== "1") { throw new Error("the viewer did not start (data-ready = " + ready + ")"); }
  await ev("document.getElementById('v3-canvas').scrollIntoView({block: 'start'}), 0");
  await sleep(200);
  // Pixels of the WebGL canvas (preserveDrawingBuffer) read through a 2D canvas: how many differ
  // from the background, and a 64 × 40 grey thumbnail to compare pictures.
  const grab = () => ev(`new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(() => {
    const c = document.getElementById('v3-canvas'), W = c.width, H = c.height;
    const t = document.createElement('canvas'); t.width = W; t.height = H;
    const g = t.getContext('2d'); g.drawImage(c, 0, 0);
    const px = g.getImageData(0, 0, W, H).data; let n = 0;
    const thumb = new Array(64 * 40).fill(0), cnt = new Array(64 * 40).fill(0);
    for (let y = 0; y < H; y++) for (let x = 0; x < W; x++) {
      const i = 4 * (y * W + x), r = px[i], gg = px[i + 1], b = px[i + 2];
      if (Math.abs(r - 251) + Math.abs(gg - 250) + Math.abs(b - 247) > 24) n++;
      const k = Math.floor(y * 40 / H) * 64 + Math.floor(x * 64 / W);
      thumb[k] += (r + gg + b) / 3; cnt[k]++;
    }
    done({ W, H, drawn: n / (W * H), thumb: thumb.map((v, k) => v / Math.max(cnt[k], 1)) });
  })))`);
  const diff = (a, b) => a.thumb.reduce((s, v, k) => s + (Math.abs(v - b.thumb[k]) > 8 ? 1 : 0), 0) / a.thumb.length;
  const shot = async (file) => {
    const rect = await ev("(() => { const r = document.getElementById('v3-canvas').getBoundingClientRect(); return {x: r.left + scrollX, y: r.top + scrollY, width: r.width, height: r.height}; })()");
    const { data } = await send("Page.captureScreenshot", { format: "png", clip: { ...rect, scale: 1 }, captureBeyondViewport: true }, s);
    writeFileSync(file, Buffer.from(data, "base64"));
  };
  const base = join(outdir, name);
  const p1 = await grab();
  await shot(base + "-1-initial.png");
  if (!(p1.drawn > 0.05)) { problems.push(`the canvas is nearly empty: ${(100 * p1.drawn).toFixed(1)} % of pixels drawn`); }

  // A real drag: press, eight moves (120 px right, 40 px down), release.
  const r = await ev("(() => { const r = document.getElementById('v3-canvas').getBoundingClientRect(); return {x: r.left + r.width / 2, y: r.top + r.height / 2}; })()");
  await send("Input.dispatchMouseEvent", { type: "mousePressed", x: r.x, y: r.y, button: "left", buttons: 1, clickCount: 1 }, s);
  for (let k = 1; k <= 8; k++) {
    await send("Input.dispatchMouseEvent", { type: "mouseMoved", x: r.x + 15 * k, y: r.y + 5 * k, button: "left", buttons: 1 }, s);
  }
  await send("Input.dispatchMouseEvent", { type: "mouseReleased", x: r.x + 120, y: r.y + 40, button: "left", buttons: 0, clickCount: 1 }, s);
  const p2 = await grab();
  await shot(base + "-2-dragged.png");
  const d12 = diff(p1, p2);
  if (!(d12 > 0.05)) { problems.push(`a drag did not change the picture (${(100 * d12).toFixed(1)} % of cells changed)`); }

  // The hook.
  await ev("window.__voussoirRotate(-200, 60), 0");
  const p3 = await grab();
  await shot(base + "-3-hook.png");
  const d23 = diff(p2, p3);
  if (!(d23 > 0.05)) { problems.push(`__voussoirRotate did not change the picture (${(100 * d23).toFixed(1)} % of cells changed)`); }

  // Slider to 0 (undeformed), then the toggles off.
  const scaled = await ev("(() => { const e = document.getElementById('v3-scale'); return !e.disabled; })()");
  let dS = null;
  if (scaled) {
    await ev("(() => { const e = document.getElementById('v3-scale'); e.value = e.max; e.dispatchEvent(new Event('input')); return 0; })()");
    const p4 = await grab();
    dS = diff(p3, p4);
    if (!(dS > 0.005)) { problems.push(`the displacement-scale slider did not change the picture (${(100 * dS).toFixed(2)} %)`); }
  }
  await ev("(() => { for (const id of ['v3-cracks', 'v3-forces']) { const e = document.getElementById(id); e.checked = false; e.dispatchEvent(new Event('change')); } return 0; })()");
  const before = await ev("window.__voussoirCounts()");
  const p5 = await grab();
  await ev("(() => { for (const id of ['v3-cracks', 'v3-forces']) { const e = document.getElementById(id); e.checked = true; e.dispatchEvent(new Event('change')); } return 0; })()");
  const after = await ev("window.__voussoirCounts()");
  const p6 = await grab();
  const dT = diff(p5, p6);
  if (!(after.triangles > before.triangles)) { problems.push("the crack/force checkboxes add no geometry"); }

  if (problems.length) { throw new Error(problems.join("\n  ")); }
  clearTimeout(timer);
  finish(0, `ok: ${report}: no console errors; canvas ${p1.W}×${p1.H}, ${(100 * p1.drawn).toFixed(1)} % drawn; ` +
    `drag changed ${(100 * d12).toFixed(1)} %, hook ${(100 * d23).toFixed(1)} %` +
    (dS === null ? ", nothing moves (slider disabled)" : `, slider ${(100 * dS).toFixed(1)} %`) +
    `; cracks+forces ${after.triangles - before.triangles} triangles (${(100 * dT).toFixed(1)} % of cells); screenshots ${base}-{1-initial,2-dragged,3-hook}.png`);
} catch (e) {
  clearTimeout(timer);
  finish(1, "error: " + e.message + (problems.length ? "\n  " + problems.join("\n  ") : ""));
}
