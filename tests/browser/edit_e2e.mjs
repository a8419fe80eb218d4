// tests/browser/edit_e2e.mjs: `scaf edit` in a real browser, end to end.
//
// usage: node edit_e2e.mjs SCAF_BINARY WORK_DIR CHROMIUM
//
// Writes a six-chart atlas (`scaf gen cubesphere`, `scaf atlas`), starts `scaf edit` on
// it, reads the URL with its token from the program's standard output,
// opens the page in headless Chromium (playwright-core, the system's
// browser: nothing downloaded), drags one chart with the mouse onto its
// neighbour, waits until the server has answered every request (the page's
// own counters, never a sleep), screenshots the page into WORK_DIR, shades
// distortion (its legend: labels and bar against the page's own colour
// scale), turns a chart (the rotate mode), drags a vertex, undoes both
// (the layout comes back number for number), checks the unit square and
// the texel grid, zooms with the wheel (the point under the cursor stays
// within a pixel), drags at that zoom (the motion asked for is the mouse's
// through the view), Ctrl-Z / Ctrl-Shift-Z / Ctrl-Y (number for number, also
// after a reload of the page), pans (middle button, space + drag, arrows:
// exactly with the mouse, no request), F fits; optimizes and compacts, clicks
// save and checks the saved file with `scaf check`: bijective, every two
// charts at least the padding apart. Then a request with a wrong token is
// refused (403) and changes nothing. The unsaved-changes mark shows after
// the first drag and goes with the save; after one more change, leaving
// the page asks first (beforeunload), and SIGTERM stops the server with
// exit status 0, the change kept in the autosave. Exit 0 pass, 1 fail.
import { spawn, spawnSync } from "node:child_process";
import { mkdirSync, rmSync, existsSync } from "node:fs";
import { createInterface } from "node:readline";
import path from "node:path";
import { chromium } from "playwright-core";

const [scaf, work, browserPath] = process.argv.slice(2);
const PADDING = 4 / 1024;

function fail(msg) {
  console.error("FAIL: " + msg);
  process.exitCode = 1;
  throw new Error(msg);
}

function run(args) {
  const r = spawnSync(scaf, args, { encoding: "utf8" });
  if (r.status !== 0) fail(`scaf ${args.join(" ")}: exit ${r.status}\n${r.stderr}`);
  return r.stdout;
}

// The first line `scaf edit` prints: its URL.
function firstLine(stream) {
  return new Promise((resolve, reject) => {
    const rl = createInterface({ input: stream });
    rl.once("line", line => resolve(line));
    stream.once("end", () => reject(new Error("scaf edit printed no URL")));
  });
}

mkdirSync(work, { recursive: true });
const input = path.join(work, "atlas.obj");
const saved = path.join(work, "edited.obj");
const shot = path.join(work, "scaf-edit.png");
const autosave = path.join(work, "edited.autosave.obj");
for (const f of [saved, shot, autosave]) rmSync(f, { force: true });
const sphere = path.join(work, "cubesphere.obj");
run(["gen", "cubesphere", "--size", "4", "-o", sphere]);
// An atlas packed to the editor's own padding (4 texels at 1024), what a
// user gets from `scaf atlas`: every gap at the padding, yet the drag
// moves chart 0 (the padding is a barrier in the drag's energy:
// app/drag_barrier, bench/RESULTS-drag.md).
run(["atlas", sphere, "-o", input, "--quiet"]);
const server = spawn(scaf, ["edit", input, "-o", saved], { stdio: ["ignore", "pipe", "inherit"] });
const exited = new Promise(resolve => server.on("exit", (code, signal) => resolve({ code, signal })));
let browser = null;
try {
  const url = await firstLine(server.stdout);
  if (!/^http:\/\/127\.0\.0\.1:\d+\/\?token=[0-9a-f]{32}$/.test(url)) fail("unexpected URL line: " + url);
  browser = await chromium.launch({
    executablePath: browserPath,
    // as root (CI containers) Chromium runs only without its sandbox;
    // containers often have a tiny /dev/shm
    args: ["--disable-dev-shm-usage"].concat(process.getuid && process.getuid() === 0 ? ["--no-sandbox"] : [])
  });
  const page = await browser.newPage({ viewport: { width: 880, height: 620 } });
  const errors = [];
  page.on("pageerror", e => errors.push(e.message));
  page.on("requestfailed", r => errors.push("request failed: " + r.url()));
  await page.goto(url);
  // waits happen in the page, on the answers of the server (no sleeps; no
  // waitForFunction: the page's Content-Security-Policy forbids its eval)
  await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.ready || window.scafEditor.error));
  const loadError = await page.evaluate(() => window.scafEditor.error);
  if (loadError) fail("the page did not load the atlas: " + loadError);

  await page.check("#checker");  // the checkerboard on the 3D surface, drawn per pixel
  // drag chart 0 onto chart 1, in small mouse steps
  const before = await page.evaluate(() => window.scafEditor.state());
  const a = await page.evaluate(() => window.scafEditor.chartPoint(0));
  const b = await page.evaluate(() => window.scafEditor.chartPoint(1));
  const ua = await page.evaluate(() => window.scafEditor.chartCentre(0));
  const ub = await page.evaluate(() => window.scafEditor.chartCentre(1));
  await page.mouse.move(a[0], a[1]);
  await page.mouse.down();
  for (let i = 1; i <= 24; i++) {
    await page.mouse.move(a[0] + (b[0] - a[0]) * i / 24, a[1] + (b[1] - a[1]) * i / 24);
    // wait until the server has answered the drag to this very position
    await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.caughtUp()));
  }
  await page.mouse.up();
  await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.idle() && window.scafEditor.state().handles === 0));
  const rigidAfter = await page.evaluate(() => window.scafEditor.state());
  // rigid by default (issue 34): no iteration ran, and every chart's UVs
  // are its UVs before the drag translated (to 1e-12 of the layout's size)
  if (rigidAfter.iteration !== before.iteration) fail("the default drag ran iterations: it is not rigid");
  const meshInfo = await page.evaluate(() => window.scafEditor.mesh());
  const vchart = new Array(before.uv.length / 2).fill(-1);
  meshInfo.faces.forEach((v, k) => { vchart[v] = meshInfo.face_chart[Math.floor(k / 3)]; });
  let size = 0;
  for (let i = 0; i < before.uv.length; i++) size = Math.max(size, Math.abs(before.uv[i]));
  const moved = new Set();
  for (let c = 0; c < meshInfo.ncharts; c++) {
    const vs = vchart.map((cc, v) => cc === c ? v : -1).filter(v => v >= 0);
    const t = [rigidAfter.uv[2 * vs[0]] - before.uv[2 * vs[0]], rigidAfter.uv[2 * vs[0] + 1] - before.uv[2 * vs[0] + 1]];
    if (Math.hypot(t[0], t[1]) > 0) moved.add(c);
    for (const v of vs)  // (the state's numbers have 9 digits: 1e-8 of the size)
      for (let k = 0; k < 2; k++)
        if (Math.abs(rigidAfter.uv[2 * v + k] - before.uv[2 * v + k] - t[k]) > 1e-7 * size)
          fail(`rigid drag: chart ${c} changed shape (vertex ${v})`);
  }
  if (!moved.has(0) || moved.size < 2) fail("rigid drag: chart 0 did not push another chart: " + [...moved]);
  console.log(`rigid drag: charts ${[...moved]} moved, shapes kept`);
  // D switches to deform: the same drag back runs SCAF iterations
  await page.keyboard.press("d");
  if (!(await page.isChecked("#deform"))) fail("D did not turn deform on");
  {
    const p0 = await page.evaluate(() => window.scafEditor.chartPoint(0));
    await page.mouse.move(p0[0], p0[1]);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++) {
      await page.mouse.move(p0[0] + (a[0] - p0[0]) * i / 24, p0[1] + (a[1] - p0[1]) * i / 24);
      await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.caughtUp()));
    }
    await page.mouse.up();
    await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.idle() && window.scafEditor.state().handles === 0));
  }
  await page.keyboard.press("d");
  // R turns the island under the pointer a quarter turn, rigidly (POST
  // /api/transform); X (a mirror) is refused and changes nothing
  {
    const s0 = await page.evaluate(() => window.scafEditor.state());
    const p2 = await page.evaluate(() => window.scafEditor.chartPoint(2));
    await page.mouse.move(p2[0], p2[1]);
    await page.keyboard.press("r");
    await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.transforms === 1 && window.scafEditor.idle()));
    const s1 = await page.evaluate(() => window.scafEditor.state());
    if (s1.iteration !== s0.iteration || JSON.stringify(s1.uv) === JSON.stringify(s0.uv) || !(s1.reached > 0))
      fail("R did not turn chart 2 rigidly: " + JSON.stringify({ reached: s1.reached, it: [s0.iteration, s1.iteration] }));
    const requests = await page.evaluate(() => window.scafEditor.answered);
    await page.keyboard.press("x");
    await page.evaluate(n => window.scafEditor.when(() => window.scafEditor.answered > n && window.scafEditor.idle()), requests);
    const s2 = await page.evaluate(() => window.scafEditor.state());
    if (JSON.stringify(s2.uv) !== JSON.stringify(s1.uv)) fail("X (flip) changed the layout");
    if (!/flip refused/.test(await page.textContent("#status"))) fail("X: no refusal shown: " + await page.textContent("#status"));
    console.log("R turned chart 2 rigidly; X refused: " + await page.textContent("#status"));
  }
  const after = await page.evaluate(() => window.scafEditor.state());
  // the mark: in the bar and in the tab's title
  const mark = async () => ({
    shown: await page.isVisible("#unsaved"), title: await page.title(),
    flag: await page.evaluate(() => window.scafEditor.unsaved)
  });
  const dragged = await mark();
  if (!dragged.shown || !dragged.flag || !dragged.title.startsWith("\u25cf"))
    fail("no unsaved-changes mark after a drag: " + JSON.stringify(dragged));
  await page.screenshot({ path: shot });  // released: the view fitted to the pushed charts
  if (!(after.iteration > before.iteration)) fail("no iteration ran while dragging in deform mode");
  // chart 0 followed the mouse toward chart 1 (pushing it aside: no overlap)
  // (layout units: the view is fitted anew on release)
  const ua2 = await page.evaluate(() => window.scafEditor.chartCentre(0));
  const dist = (p, q) => Math.hypot(p[0] - q[0], p[1] - q[1]);
  console.log(`chart 0: distance to chart 1 ${dist(ua, ub)} -> ${dist(ua2, ub)}`);
  if (!(dist(ua2, ub) < 0.5 * dist(ua, ub))) fail(`chart 0 did not follow the drag: ${ua} -> ${ua2}, toward ${ub}`);

  // distortion shading: the server's per-face energies, >= 4 (isometry)
  await page.check("#distortion");
  const energies = await page.evaluate(() => window.scafEditor.when(() => {
    const d = window.scafEditor.distortion();
    return d && d.iteration === window.scafEditor.state().iteration;
  }).then(() => window.scafEditor.distortion().face_energy));
  if (energies.length !== 192 || !energies.every(e => e >= 4 - 1e-9))
    fail("distortion: " + energies.length + " faces, min " + Math.min(...energies));
  // the legend shows with the shading: its bar painted with the page's
  // own colour scale at every tick, its labels that scale's numbers
  if (!(await page.isVisible("#legend"))) fail("no legend beside the distortion shading");
  const legend = await page.evaluate(() => {
    const bar = document.getElementById("legend-bar").getContext("2d");
    const texts = [...document.querySelectorAll("#legend-ticks span")].map(t => t.textContent);
    return { texts, ticks: window.scafEditor.legend().map(t => {
      const d = bar.getImageData(t.column, 6, 1, 1).data;
      return { label: t.label, value: t.value, bar: [d[0], d[1], d[2]], heat: window.scafEditor.heat(t.value) };
    }) };
  });
  const rgb = c => c.match(/\d+/g).map(Number);
  if (legend.texts.join(" ") !== "4 5 6 7 8+" || legend.ticks.map(t => t.label).join(" ") !== "4 5 6 7 8+")
    fail("legend labels: " + JSON.stringify(legend.texts));
  for (const t of legend.ticks) {
    const want = rgb(t.heat);
    if (want.some((c, k) => Math.abs(c - t.bar[k]) > 2)) fail(`legend at ${t.label}: bar ${t.bar}, the shading ${t.heat}`);
  }
  if (legend.ticks[0].heat !== "rgb(255,255,255)" || legend.ticks[4].heat !== "rgb(255,0,0)")
    fail("the shading's scale is not white at 4 .. red at 8: " + JSON.stringify(legend.ticks));
  await page.screenshot({ path: path.join(work, "scaf-edit-distortion.png") });

  // a rotation (shift + drag) and a vertex drag (the radio button), then
  // undo twice with the button: back to the layout after the first drag,
  // number for number
  const kept = JSON.stringify((await page.evaluate(() => window.scafEditor.state())).uv);
  const settled = () => page.evaluate(() => window.scafEditor.when(
    () => window.scafEditor.idle() && window.scafEditor.state().handles === 0));
  async function mouseDrag(from, to, n) {
    await page.mouse.move(from[0], from[1]);
    await page.mouse.down();
    for (let i = 1; i <= n; i++) {
      await page.mouse.move(from[0] + (to[0] - from[0]) * i / n, from[1] + (to[1] - from[1]) * i / n);
      await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.caughtUp()));
    }
    await page.mouse.up();
    await settled();
  }
  const c2 = await page.evaluate(() => window.scafEditor.chartPoint(2));
  await page.check("input[value=rotate]");  // (shift-click selects: tools/edit_page_tools.js)
  await mouseDrag([c2[0] + 30, c2[1]], [c2[0], c2[1] - 30], 6);  // a quarter turn
  await page.check("input[value=move]");
  const turned = await page.evaluate(() => window.scafEditor.state());
  if (JSON.stringify(turned.uv) === kept) fail("the rotation moved nothing");
  await page.check("input[value=vertex]");
  const c3 = await page.evaluate(() => window.scafEditor.chartPoint(3));
  await mouseDrag(c3, [c3[0] + 12, c3[1] + 12], 3);
  await page.check("input[value=move]");
  const undoOnce = async () => {
    await page.click("#undo");
    await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.idle()));
  };
  await undoOnce();
  await undoOnce();
  if (JSON.stringify((await page.evaluate(() => window.scafEditor.state())).uv) !== kept)
    fail("two undos did not restore the layout after the first drag");

  // ---- the view: zoom to the cursor, pan, fit; the unit square and texels
  const editor = fn => page.evaluate(fn);
  const viewChanges = () => editor(() => window.scafEditor.viewChanges);
  const view = () => editor(() => window.scafEditor.view());
  const toPage = uv => page.evaluate(uv => window.scafEditor.toPage(uv[0], uv[1]), uv);
  const toLayout = p => page.evaluate(p => window.scafEditor.toLayout(p[0], p[1]), p);
  // a key whose request the page sends at once; waits for its answer
  const pressAndWait = async key => {
    const r0 = await editor(() => window.scafEditor.requests);
    await page.keyboard.press(key);
    await page.evaluate(r0 => window.scafEditor.when(() => window.scafEditor.requests > r0 && window.scafEditor.idle()), r0);
  };
  const near = (p, q, tol) => Math.hypot(p[0] - q[0], p[1] - q[1]) <= tol;
  // the unit square: the save's normalization (lower corner, longer side)
  const fr = await editor(() => window.scafEditor.frame());
  {
    const uv = (await editor(() => window.scafEditor.state())).uv;
    const us = uv.filter((_, i) => i % 2 === 0), vs = uv.filter((_, i) => i % 2 === 1);
    const side = Math.max(Math.max(...us) - Math.min(...us), Math.max(...vs) - Math.min(...vs));
    if (fr.u !== Math.min(...us) || fr.v !== Math.min(...vs) || fr.side !== side) fail("unit square " + JSON.stringify(fr));
  }
  // fitted: a texel of 1024 is under a pixel, no grid; 64 texels show one
  const sidePixels = async () => (await toPage([fr.u + fr.side, fr.v]))[0] - (await toPage([fr.u, fr.v]))[0];
  if (await editor(() => window.scafEditor.grid())) fail("a texel grid at 1024 texels in the fitted view");
  await page.fill("#resolution", "64");
  const grid64 = await editor(() => window.scafEditor.grid());
  if (!grid64 || grid64.resolution !== 64 || Math.abs(grid64.texelPixels - await sidePixels() / 64) > 1e-9 ||
      grid64.lines !== 130)
    fail("texel grid at 64: " + JSON.stringify(grid64));
  await page.fill("#resolution", "1024");
  // the wheel over a point keeps that layout point under the cursor
  const c4 = await editor(() => window.scafEditor.chartPoint(4));
  // (whole pixels: Chromium's wheel events carry integer clientX/Y)
  const cursor = [Math.round(c4[0]) + 17, Math.round(c4[1]) - 10];
  const under = await toLayout(cursor);
  const s0 = (await view()).s;
  await page.mouse.move(cursor[0], cursor[1]);
  await page.mouse.wheel(0, -1500);  // fifteen notches in: 1.25^15
  await page.evaluate(s0 => window.scafEditor.when(
    () => Math.abs(window.scafEditor.view().s / s0 - Math.pow(1.25, 15)) < 1e-9), s0);
  const back = await toPage(under);
  console.log(`zoom x${((await view()).s / s0).toFixed(3)}: the point under the cursor moved ` +
              `${Math.hypot(back[0] - cursor[0], back[1] - cursor[1]).toExponential(2)} px`);
  if (!near(back, cursor, 1)) fail(`zoom: the point under the cursor went from ${cursor} to ${back}`);
  const grid = await editor(() => window.scafEditor.grid());
  if (!grid || grid.resolution !== 1024 || !(grid.texelPixels >= 4)) fail("no texel grid zoomed in: " + JSON.stringify(grid));
  await page.screenshot({ path: path.join(work, "scaf-edit-zoom.png") });
  // dragging at this zoom: the motion asked for is the mouse's through the view
  {
    const kept2 = JSON.stringify((await editor(() => window.scafEditor.state())).uv);
    const s = (await view()).s, dpr = await editor(() => window.devicePixelRatio);
    await mouseDrag(cursor, [cursor[0] + 40, cursor[1] + 24], 4);
    const motion = await editor(() => window.scafEditor.lastDrag);
    if (motion.chart !== 4 || Math.abs(motion.dx - 40 * dpr / s) > 1e-9 * Math.abs(motion.dx) ||
        Math.abs(motion.dy + 24 * dpr / s) > 1e-9 * Math.abs(motion.dy))
      fail(`drag at zoom: asked ${JSON.stringify(motion)} for 40, 24 px at scale ${s}`);
    const moved = await editor(() => window.scafEditor.state());
    if (JSON.stringify(moved.uv) === kept2) fail("a drag at zoom moved nothing");
    if ((await view()).s !== s) fail("the release refitted the zoomed view");
    // Ctrl-Z: back to the layout before that drag, number for number
    await pressAndWait("Control+z");
    const uvNow = async () => JSON.stringify((await editor(() => window.scafEditor.state())).uv);
    if (await uvNow() !== kept2) fail("Ctrl-Z did not restore the layout before the drag");
    // Ctrl-Shift-Z and Ctrl-Y: the dragged layout again, number for number
    await pressAndWait("Control+Shift+z");
    if (await uvNow() !== JSON.stringify(moved.uv)) fail("Ctrl-Shift-Z did not redo the drag");
    if (!(await page.isDisabled("#redo"))) fail("redo enabled with nothing to redo");
    await pressAndWait("Control+z");
    await pressAndWait("Control+y");
    if (await uvNow() !== JSON.stringify(moved.uv)) fail("Ctrl-Y did not redo the drag");
    // the history is the server's: a reload of the page undoes the same
    const leave = d => d.accept();  // the unsaved-changes question: leave
    page.on("dialog", leave);
    await page.reload();
    page.off("dialog", leave);
    await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.ready || window.scafEditor.error));
    if (await uvNow() !== JSON.stringify(moved.uv)) fail("the reload did not show the layout");
    await pressAndWait("Control+z");
    if (await uvNow() !== kept2) fail("after a reload Ctrl-Z did not restore the layout before the drag");
    await page.mouse.move(cursor[0], cursor[1]);
    await page.mouse.wheel(0, -1500);  // the zoom again (the reload fitted the view)
    await page.evaluate(s0 => window.scafEditor.when(
      () => Math.abs(window.scafEditor.view().s / s0 - Math.pow(1.25, 15)) < 1e-9), s0);
  }
  // pan: the middle button and space + left button move the view with the
  // mouse, exactly, and never the layout
  const requests0 = await editor(() => window.scafEditor.requests);
  for (const how of ["middle", "space"]) {
    const p = await toPage(under), n = await viewChanges();
    await page.mouse.move(p[0], p[1]);
    if (how === "space") await page.keyboard.down(" ");
    await page.mouse.down({ button: how === "middle" ? "middle" : "left" });
    await page.mouse.move(p[0] - 30, p[1] + 20);
    await page.mouse.up({ button: how === "middle" ? "middle" : "left" });
    if (how === "space") await page.keyboard.up(" ");
    await page.evaluate(n => window.scafEditor.when(() => window.scafEditor.viewChanges > n), n);
    const q = await toPage(under);
    if (!near(q, [p[0] - 30, p[1] + 20], 1e-6)) fail(`pan (${how}): ${p} -> ${q}, not by (-30, 20)`);
  }
  if ((await editor(() => window.scafEditor.requests)) !== requests0) fail("panning sent requests");
  // arrow keys: a tenth of the view; F: the fit
  {
    const v0 = await view(), n = await viewChanges();
    await page.keyboard.press("ArrowRight");
    await page.evaluate(n => window.scafEditor.when(() => window.scafEditor.viewChanges > n), n);
    const v1 = await view();
    const w = await editor(() => Math.min(document.getElementById("view").width, document.getElementById("view").height));
    if (v1.s !== v0.s || Math.abs(v1.ox - (v0.ox - 0.1 * w)) > 1e-9 || v1.oy !== v0.oy)
      fail(`ArrowRight: ${JSON.stringify(v0)} -> ${JSON.stringify(v1)}`);
    await page.keyboard.press("f");
    await page.evaluate(n => window.scafEditor.when(() => window.scafEditor.view().fitted), n);
    const fitted = await view();
    await page.click("#fit");
    const again = await view();
    if (JSON.stringify(fitted) !== JSON.stringify(again))
      fail(`F and the fit button differ: ${JSON.stringify(fitted)} ${JSON.stringify(again)}`);
    const box = await page.locator("#view").boundingBox();
    for (let c = 0; c < 6; c++) {
      const q = await page.evaluate(c => window.scafEditor.chartPoint(c), c);
      if (!(q[0] > box.x && q[0] < box.x + box.width && q[1] > box.y && q[1] < box.y + box.height))
        fail(`after F chart ${c} is outside the view: ${q}`);
    }
  }

  for (const button of ["#optimize", "#compact"]) {
    await page.click(button);
    await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.idle()));
  }
  const buttonError = await page.evaluate(() => window.scafEditor.error);
  if (buttonError) fail(buttonError);

  await page.click("#save");
  await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.saved || window.scafEditor.error));
  const saveError = await page.evaluate(() => window.scafEditor.error);
  if (saveError) fail("save: " + saveError);
  if (!existsSync(saved)) fail("save reported success but " + saved + " is missing");
  const check = spawnSync(scaf, ["check", saved], { encoding: "utf8" });
  if (check.status !== 0) fail(`scaf check ${saved}: exit ${check.status}\n${check.stdout}`);
  const gap = Number((/min chart gap\s+(\S+)/.exec(check.stdout) || [])[1]);
  if (!(gap >= PADDING)) fail(`saved atlas: min chart gap ${gap} below the padding ${PADDING}`);
  if (!/charts\s+6\b/.test(check.stdout)) fail("saved atlas does not have 6 charts:\n" + check.stdout);
  const savedMark = await mark();
  if (savedMark.shown || savedMark.flag || savedMark.title.startsWith("\u25cf"))
    fail("the unsaved-changes mark stayed after the save: " + JSON.stringify(savedMark));

  // a request without the token is refused and changes nothing
  const refused = await page.evaluate(async () => {
    const s0 = JSON.stringify(window.scafEditor.state().uv);
    const r = await fetch("/api/drag", { method: "POST", body: '{"chart": 0, "dx": 1, "dy": 0, "angle": 0}' });
    const s1 = await (await fetch("/api/state", { headers: { "X-Scaf-Token": new URLSearchParams(location.search).get("token") } })).json();
    return { status: r.status, same: JSON.stringify(s1.uv.map(x => Number(x))) === s0 };
  });
  if (refused.status !== 403 || !refused.same) fail("a request without token: " + JSON.stringify(refused));
  if (errors.length) fail("page errors: " + errors.join("; "));

  // one more change: marked again, and leaving the page asks first
  await page.click("#optimize");
  await page.evaluate(() => window.scafEditor.when(() => window.scafEditor.idle()));
  if (!(await mark()).shown) fail("no unsaved-changes mark after optimize");
  // (a reload: this Chromium's headless close skips the dialog, a
  // navigation away from the page shows it)
  const asked = new Promise(resolve => {
    page.once("dialog", async d => {
      const type = d.type();
      await d.dismiss();  // stay on the page
      resolve(type);
    });
    page.once("load", () => resolve("none: the page reloaded"));
  });
  page.reload({ timeout: 0 }).catch(() => {});  // pending while the dialog holds it
  const dialog = await asked;
  if (dialog !== "beforeunload") fail("leaving the page with unsaved changes: dialog " + dialog);
  if (!(await page.evaluate(() => window.scafEditor.unsaved))) fail("the page left without asking");
  console.log(`scaf edit in ${await browser.version()}: ${after.iteration - before.iteration} iterations ` +
              `while dragging, saved ${saved} (bijective, min chart gap ${gap} >= ${PADDING}), ` +
              `screenshot ${shot}`);
} catch (e) {
  if (!process.exitCode) console.error("FAIL: " + (e.stack || e));
  process.exitCode = 1;
} finally {
  if (browser) await browser.close();
  server.kill("SIGTERM");
  const { code, signal } = await exited;
  if (code !== 0) {
    console.error(`FAIL: scaf edit ended with ${code === null ? "signal " + signal : "exit " + code} after SIGTERM`);
    process.exitCode = 1;
  } else if (!process.exitCode) {
    // the change after the save is in the autosave, certified
    const check = spawnSync(scaf, ["check", autosave], { encoding: "utf8" });
    if (check.status !== 0) {
      console.error(`FAIL: the autosave ${autosave} after SIGTERM: scaf check exit ${check.status}`);
      process.exitCode = 1;
    }
  }
  rmSync(autosave, { force: true });  // the next run starts afresh
}
