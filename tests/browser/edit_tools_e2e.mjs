// tests/browser/edit_tools_e2e.mjs: the tools of `scaf edit`'s page
// (tools/edit_page_tools.js) in a real browser, through the page itself.
//
// usage: node edit_tools_e2e.mjs SCAF_BINARY WORK_DIR CHROMIUM
//
// Writes a six-chart atlas and a 64 x 64 PNG (a gradient: red along u,
// green along v), starts `scaf edit --texture` on them and opens the page
// in headless Chromium (software WebGL). Then, waiting only on the page's
// own counters: the texture is served and drawn under the layout (a
// pixel of the view where no chart is has the texture's colour at that
// point of the unit square); the 3D view renders the model (pixels read
// back from WebGL: not blank, many colours), changes when a chart is
// dragged (live UVs), when the mouse orbits it, and lights the hovered
// island (hover in the 2D view highlights in both; hover in the 3D view
// names the island in both); selection: click, shift-click, Escape, a box
// on empty space, ctrl + box over the charts, vertex clicks and a vertex
// box (counts from window.scafEditor.selection()); pins: the P button
// pins the selected vertices (the ids in /api/state), they keep their
// bits through a drag of their island, survive a reload of the page, and
// U unpins; the padding field: a smaller padding is sent with compact and
// kept by the save (`scaf check`), a larger one than the layout keeps is
// refused with the server's reason, a bad value sends nothing. Screenshots
// go to WORK_DIR (scaf-edit.png: the README's picture, docs/scaf-edit.png).
// Exit 0 pass, 1 fail.
import { spawn, spawnSync } from "node:child_process";
import { mkdirSync, rmSync, existsSync, writeFileSync } from "node:fs";
import { createInterface } from "node:readline";
import { deflateSync } from "node:zlib";
import path from "node:path";
import { chromium } from "playwright-core";

const [scaf, work, browserPath] = process.argv.slice(2);

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
function firstLine(stream) {
  return new Promise((resolve, reject) => {
    const rl = createInterface({ input: stream });
    rl.once("line", line => resolve(line));
    stream.once("end", () => reject(new Error("scaf edit printed no URL")));
  });
}

// A PNG of n x n RGB pixels: (4 x, 4 (n - 1 - row), 128): red grows along
// u, green along v (row 0 is the top of the image: v = 1).
function gradientPng(n) {
  const crcTable = Array.from({ length: 256 }, (_, k) => {
    let c = k;
    for (let i = 0; i < 8; i++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
  });
  const crc = b => { let c = 0xffffffff; for (const x of b) c = crcTable[(c ^ x) & 255] ^ (c >>> 8); return (c ^ 0xffffffff) >>> 0; };
  const chunk = (type, data) => {
    const out = Buffer.alloc(12 + data.length);
    out.writeUInt32BE(data.length, 0);
    out.write(type, 4, "latin1");
    data.copy(out, 8);
    out.writeUInt32BE(crc(out.subarray(4, 8 + data.length)), 8 + data.length);
    return out;
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(n, 0); ihdr.writeUInt32BE(n, 4);
  ihdr[8] = 8; ihdr[9] = 2;  // 8 bits, RGB
  const raw = Buffer.alloc(n * (1 + 3 * n));
  for (let y = 0; y < n; y++) {
    raw[y * (1 + 3 * n)] = 0;
    for (let x = 0; x < n; x++) {
      const o = y * (1 + 3 * n) + 1 + 3 * x;
      raw[o] = 4 * x; raw[o + 1] = 4 * (n - 1 - y); raw[o + 2] = 128;
    }
  }
  return Buffer.concat([Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]), chunk("IHDR", ihdr),
                        chunk("IDAT", deflateSync(raw)), chunk("IEND", Buffer.alloc(0))]);
}

mkdirSync(work, { recursive: true });
const input = path.join(work, "atlas.obj");
const saved = path.join(work, "edited.obj");
const autosave = path.join(work, "edited.autosave.obj");
const texture = path.join(work, "gradient.png");
for (const f of [saved, autosave]) rmSync(f, { force: true });
writeFileSync(texture, gradientPng(64));
const sphere = path.join(work, "cubesphere.obj");
run(["gen", "cubesphere", "--size", "4", "-o", sphere]);
run(["atlas", sphere, "-o", input, "--quiet"]);
const server = spawn(scaf, ["edit", input, "-o", saved, "--texture", texture, "--quiet"],
                     { stdio: ["ignore", "pipe", "inherit"] });
const exited = new Promise(resolve => server.on("exit", (code, signal) => resolve({ code, signal })));
let browser = null;
try {
  const url = await firstLine(server.stdout);
  if (!/^http:\/\/127\.0\.0\.1:\d+\/\?token=[0-9a-f]{32}$/.test(url)) fail("unexpected URL line: " + url);
  browser = await chromium.launch({
    executablePath: browserPath,
    // WebGL without a GPU: SwiftShader, which Chromium now uses only when asked
    args: ["--disable-dev-shm-usage", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist"]
      .concat(process.getuid && process.getuid() === 0 ? ["--no-sandbox"] : [])
  });
  const page = await browser.newPage({ viewport: { width: 1100, height: 640 } });
  const errors = [];
  page.on("pageerror", e => errors.push(e.message));
  page.on("requestfailed", r => errors.push("request failed: " + r.url()));
  const ed = (fn, arg) => page.evaluate(fn, arg);
  // (no waitForFunction: the page's Content-Security-Policy forbids its eval)
  const loaded = () => ed(() => window.scafEditor.when(() =>
    (window.scafEditor.ready && window.scafEditor.toolsReady && window.scafEditor.texture().loaded) || window.scafEditor.error));
  const idle = () => ed(() => window.scafEditor.when(() => window.scafEditor.idle() && window.scafEditor.state().handles === 0));
  await page.goto(url);
  await loaded();
  const loadError = await ed(() => window.scafEditor.error);
  if (loadError) fail("the page did not load: " + loadError);

  // ---- the texture under the UVs ------------------------------------------------
  const tex = await ed(() => window.scafEditor.texture());
  if (!tex.given || !tex.loaded || tex.width !== 64 || tex.height !== 64 || tex.shown !== "texture" || !tex.under)
    fail("texture: " + JSON.stringify(tex));
  // a point of the unit square where no chart is: the texture's colour there
  const probe = await ed(() => {
    const fr = window.scafEditor.frame(), cv = document.getElementById("view"), g = cv.getContext("2d");
    const r = cv.getBoundingClientRect(), dpr = cv.width / r.width;
    for (let i = 3; i < 40; i++) for (let j = 3; j < 40; j++) {
      const s = (i + 0.5) / 43, t = (j + 0.5) / 43, u = fr.u + s * fr.side, v = fr.v + t * fr.side;
      const [x, y] = window.scafEditor.toPage(u, v);
      const px = Math.round((x - r.left) * dpr), py = Math.round((y - r.top) * dpr);
      // far from every chart: no face within 6 pixels
      let clear = true;
      for (const [dx, dy] of [[0, 0], [6, 0], [-6, 0], [0, 6], [0, -6], [4, 4], [-4, -4], [4, -4], [-4, 4]]) {
        const q = window.scafEditor.toLayout(x + dx / dpr, y + dy / dpr);
        if (faceAt(q[0], q[1]) >= 0) clear = false;
      }
      if (!clear) continue;
      const d = g.getImageData(px, py, 1, 1).data;
      return { s, t, rgb: [d[0], d[1], d[2]] };
    }
    return null;
  });
  if (!probe) fail("no empty point in the unit square to look at the texture");
  const want = [4 * Math.min(63, Math.floor(probe.s * 64)), 4 * Math.min(63, Math.floor(probe.t * 64)), 128];
  console.log(`texture under the UVs at (${probe.s.toFixed(3)}, ${probe.t.toFixed(3)}): ${probe.rgb}, the image ${want}`);
  if (probe.rgb.some((c, k) => Math.abs(c - want[k]) > 10)) fail(`texture pixel ${probe.rgb}, want ${want}`);
  // the server sends the image with the token only
  const texStatus = await ed(async () => [(await fetch("/texture.png")).status,
    (await fetch("/texture.png?token=" + new URLSearchParams(location.search).get("token"))).headers.get("content-type")]);
  if (texStatus[0] !== 403 || texStatus[1] !== "image/png") fail("/texture.png: " + JSON.stringify(texStatus));

  // ---- the 3D view -----------------------------------------------------------------
  const v3 = await ed(() => window.scafEditor.view3d());
  if (!v3.ready) fail("no 3D view: " + v3.note);
  const pix = () => ed(() => window.scafEditor.pixels3d());
  const p0 = await pix();
  console.log(`3D view: ${p0.width} x ${p0.height}, ${p0.other} pixels of the model, ${p0.colours} colours`);
  if (!(p0.other > 0.05 * p0.width * p0.height) || !(p0.colours > 20)) fail("the 3D view is blank: " + JSON.stringify(p0));
  // the checker instead of the texture: another picture
  await page.selectOption("#image", "checker");
  const pChecker = await pix();
  if (pChecker.sum === p0.sum) fail("the 3D view did not change with the checker");
  await page.selectOption("#image", "texture");
  // orbit: the mouse turns the model
  const box3 = await page.locator("#canvas3d").boundingBox();
  const c3 = [box3.x + box3.width / 2, box3.y + box3.height / 2];
  {
    const before = await pix(), n = await ed(() => window.scafEditor.orbits);
    await page.mouse.move(c3[0] - 40, c3[1]);
    await page.mouse.down();
    await page.mouse.move(c3[0] + 20, c3[1] + 15, { steps: 3 });
    await page.mouse.up();
    await ed(n => window.scafEditor.when(() => window.scafEditor.orbits > n), n);
    if ((await pix()).sum === before.sum) fail("orbiting did not change the 3D view");
  }
  // hover in the 3D view: the island under the mouse, in both views
  {
    const n = await ed(() => window.scafEditor.hoverChanges);
    await page.mouse.move(c3[0], c3[1]);
    await ed(n => window.scafEditor.when(() => window.scafEditor.hoverChanges > n), n);
    const h = await ed(() => window.scafEditor.hovered());
    if (!(h >= 0 && h < 6)) fail("hover in the 3D view: island " + h);
    await page.mouse.move(box3.x + 3, box3.y + 3);  // the background
    await ed(() => window.scafEditor.when(() => window.scafEditor.hovered() === -1));
  }
  // hover in the 2D view lights the island in the 3D view too
  {
    const plain = await pix();
    const q = await ed(() => window.scafEditor.chartPoint(2));
    await page.mouse.move(q[0], q[1]);
    await ed(() => window.scafEditor.when(() => window.scafEditor.hovered() === 2));
    const lit = await pix();
    if (lit.sum === plain.sum) fail("hovering island 2 in the 2D view did not light it in the 3D view");
  }
  await page.screenshot({ path: path.join(work, "scaf-edit-3d.png") });
  // live: a drag changes the UVs on the 3D model as it goes
  const mouseDrag = async (from, to, n) => {
    await page.mouse.move(from[0], from[1]);
    await page.mouse.down();
    for (let i = 1; i <= n; i++) {
      await page.mouse.move(from[0] + (to[0] - from[0]) * i / n, from[1] + (to[1] - from[1]) * i / n);
      await ed(() => window.scafEditor.when(() => window.scafEditor.caughtUp()));
    }
    await page.mouse.up();
    await idle();
  };
  {
    const before = await pix(), r0 = await ed(() => window.scafEditor.view3d().renders);
    const a = await ed(() => window.scafEditor.chartPoint(0)), b = await ed(() => window.scafEditor.chartPoint(1));
    await mouseDrag(a, [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2], 4);
    const after = await pix(), r1 = await ed(() => window.scafEditor.view3d().renders);
    if (!(r1 >= r0 + 4) || after.sum === before.sum) fail(`3D view after a drag: renders ${r0} -> ${r1}, picture changed ${after.sum !== before.sum}`);
  }

  // the README's picture: an island selected (the drag's click), another
  // hovered, the checker under the UVs and on the 3D view
  await page.selectOption("#image", "checker");
  {
    const q = await ed(() => window.scafEditor.chartPoint(2));
    await page.mouse.move(q[0], q[1]);
    await ed(() => window.scafEditor.when(() => window.scafEditor.hovered() === 2));
  }
  await page.screenshot({ path: path.join(work, "scaf-edit.png") });
  await page.selectOption("#image", "texture");

  // ---- selection -----------------------------------------------------------------------
  const sel = () => ed(() => window.scafEditor.selection());
  const same = (x, y) => JSON.stringify(x) === JSON.stringify(y);
  {
    const s = await sel();  // the drag's click selected chart 0
    if (!same(s, { charts: [0], vertices: [] })) fail("a click on chart 0: " + JSON.stringify(s));
  }
  const clickAt = async (p, modifiers) => {
    const n = await ed(() => window.scafEditor.selectionChanges);
    for (const m of modifiers || []) await page.keyboard.down(m);
    await page.mouse.click(p[0], p[1]);
    for (const m of modifiers || []) await page.keyboard.up(m);
    await ed(n => window.scafEditor.when(() => window.scafEditor.selectionChanges > n && window.scafEditor.idle()), n);
  };
  await clickAt(await ed(() => window.scafEditor.chartPoint(3)), ["Shift"]);
  await clickAt(await ed(() => window.scafEditor.chartPoint(5)), ["Shift"]);
  if (!same(await sel(), { charts: [0, 3, 5], vertices: [] })) fail("shift-click: " + JSON.stringify(await sel()));
  await clickAt(await ed(() => window.scafEditor.chartPoint(0)), ["Shift"]);
  if (!same(await sel(), { charts: [3, 5], vertices: [] })) fail("shift-click again: " + JSON.stringify(await sel()));
  {
    const n = await ed(() => window.scafEditor.selectionChanges);
    await page.keyboard.press("Escape");
    await ed(n => window.scafEditor.when(() => window.scafEditor.selectionChanges > n), n);
    if (!same(await sel(), { charts: [], vertices: [] })) fail("Escape: " + JSON.stringify(await sel()));
  }
  const boxDrag = async (from, to, modifiers) => {
    const n = await ed(() => window.scafEditor.selectionChanges), r0 = await ed(() => window.scafEditor.requests);
    for (const m of modifiers || []) await page.keyboard.down(m);
    await page.mouse.move(from[0], from[1]);
    await page.mouse.down();
    await page.mouse.move(to[0], to[1], { steps: 4 });
    await page.mouse.up();
    for (const m of modifiers || []) await page.keyboard.up(m);
    await ed(n => window.scafEditor.when(() => window.scafEditor.selectionChanges > n), n);
    if ((await ed(() => window.scafEditor.requests)) !== r0) fail("a box selection sent requests");
  };
  const view2 = await page.locator("#view").boundingBox();
  // a box from the empty corner over everything: the six islands
  await boxDrag([view2.x + 4, view2.y + 4], [view2.x + view2.width - 4, view2.y + view2.height - 4]);
  if (!same(await sel(), { charts: [0, 1, 2, 3, 4, 5], vertices: [] })) fail("box over all: " + JSON.stringify(await sel()));
  await page.screenshot({ path: path.join(work, "scaf-edit-selection.png") });
  // ctrl + a box starting on a chart: only what it covers (a small box on chart 4)
  {
    const q = await ed(() => window.scafEditor.chartPoint(4));
    await boxDrag([q[0] - 25, q[1] - 25], [q[0] + 25, q[1] + 25], ["Control"]);
    const s = await sel();
    if (!s.charts.includes(4) || s.charts.length >= 6) fail("ctrl + box on chart 4: " + JSON.stringify(s));
  }
  // vertices: the toggle, a click on a vertex, shift-click another, a box
  await page.check("input[name=selmode][value=vertex]");
  const vertexPoint = i => ed(i => { const uv = window.scafEditor.state().uv; return window.scafEditor.toPage(uv[2 * i], uv[2 * i + 1]); }, i);
  // two vertices of chart 1, on its boundary and far apart
  const [va, vb] = await ed(() => {
    const C = window.scafEditor.state && mesh.face_chart, F = mesh.faces, seen = [];
    for (let f = 0; f < C.length; f++) if (C[f] === 1) for (let k = 0; k < 3; k++) if (!seen.includes(F[3 * f + k])) seen.push(F[3 * f + k]);
    return [seen[0], seen[seen.length - 1]];
  });
  await clickAt(await vertexPoint(va));
  if (!same(await sel(), { charts: [], vertices: [va] })) fail(`a click on vertex ${va}: ` + JSON.stringify(await sel()));
  await clickAt(await vertexPoint(vb), ["Shift"]);
  if (!same(await sel(), { charts: [], vertices: [va, vb].sort((a, b) => a - b) })) fail("shift-click a vertex: " + JSON.stringify(await sel()));

  // ---- pins ---------------------------------------------------------------------------
  const apiState = () => ed(async () => (await fetch("/api/state", { headers: { "X-Scaf-Token": new URLSearchParams(location.search).get("token") } })).json());
  {
    const r0 = await ed(() => window.scafEditor.requests);
    await page.click("#pin");
    await ed(r0 => window.scafEditor.when(() => window.scafEditor.requests >= r0 + 2 && window.scafEditor.idle()), r0);
    const s = await apiState();
    const want = [va, vb].sort((a, b) => a - b);
    if (!same(s.pinned_vertices, want) || s.pinned !== 2) fail(`pinned ${JSON.stringify(s.pinned_vertices)}, want ${want}`);
    if (!same(await ed(() => window.scafEditor.pinned()), want)) fail("the page's pins differ from the server's");
  }
  await page.screenshot({ path: path.join(work, "scaf-edit-pins.png") });
  // a deform drag of their island (a chart with pins never moves rigidly):
  // the pinned vertices keep their bits
  {
    const s0 = await apiState();
    await page.check("input[name=selmode][value=island]");
    await page.check("#deform");
    const q = await ed(() => window.scafEditor.chartPoint(1));
    await mouseDrag(q, [q[0] + 30, q[1] - 20], 4);
    await page.uncheck("#deform");
    const s1 = await apiState();
    if (s1.iteration === s0.iteration) fail("the drag of chart 1 ran no iteration");
    for (const i of [va, vb])
      if (s1.uv[2 * i] !== s0.uv[2 * i] || s1.uv[2 * i + 1] !== s0.uv[2 * i + 1])
        fail(`pinned vertex ${i} moved: ${s0.uv.slice(2 * i, 2 * i + 2)} -> ${s1.uv.slice(2 * i, 2 * i + 2)}`);
  }
  // a reload: the pins are the server's
  {
    const leave = d => d.accept();
    page.on("dialog", leave);
    await page.reload();
    page.off("dialog", leave);
    await loaded();
    const want = [va, vb].sort((a, b) => a - b);
    if (!same(await ed(() => window.scafEditor.pinned()), want)) fail("pins after a reload: " + JSON.stringify(await ed(() => window.scafEditor.pinned())));
    // U unpins the selected vertex
    await page.check("input[name=selmode][value=vertex]");
    await clickAt(await vertexPoint(va));
    const r0 = await ed(() => window.scafEditor.requests);
    await page.keyboard.press("u");
    await ed(r0 => window.scafEditor.when(() => window.scafEditor.requests > r0 && window.scafEditor.idle()), r0);
    const s = await apiState();
    if (!same(s.pinned_vertices, [vb])) fail("after U: pinned " + JSON.stringify(s.pinned_vertices));
    // a box of vertices around chart 2's centre
    const q = await ed(() => window.scafEditor.chartPoint(2));
    await boxDrag([q[0] - 30, q[1] - 30], [q[0] + 30, q[1] + 30]);
    const sv = await sel();
    const charts = await ed(v => v.map(i => { for (let f = 0; f < mesh.faces.length; f++) if (mesh.faces[f] === i) return mesh.face_chart[Math.floor(f / 3)]; return -1; }), sv.vertices);
    if (!(sv.vertices.length >= 1) || sv.charts.length || !charts.every(c => c === 2)) fail("vertex box on chart 2: " + JSON.stringify(sv) + " charts " + charts);
    await page.check("input[name=selmode][value=island]");
  }

  // ---- the padding of compact --------------------------------------------------------------
  {
    const pad0 = (await apiState()).padding;
    if (pad0 !== 4 / 1024) fail("starting padding " + pad0);
    if ((await page.inputValue("#padding-texels")) !== "4") fail("padding field " + await page.inputValue("#padding-texels"));
    // a bad value: marked, nothing sent
    await page.fill("#padding-texels", "-1");
    const r0 = await ed(() => window.scafEditor.requests);
    await page.click("#compact");
    if ((await ed(() => window.scafEditor.requests)) !== r0) fail("compact with padding -1 sent a request");
    if (!(await ed(() => document.getElementById("padding-texels").classList.contains("bad")))) fail("padding -1 not marked");
    await ed(() => { window.scafEditor.error = null; });
    // more than the layout keeps: the server says no, nothing changes
    await page.fill("#padding-texels", "200");
    await page.click("#compact");
    await ed(() => window.scafEditor.when(() => window.scafEditor.idle() && window.scafEditor.error));
    const refused = await ed(() => window.scafEditor.error);
    if (!/padding/.test(refused) || (await apiState()).padding !== pad0) fail("padding 200 texels: " + refused);
    console.log("padding 200 texels refused: " + refused);
    await ed(() => { window.scafEditor.error = null; });
    // 3 texels: compact packs to it, the state and the save keep it
    await page.fill("#padding-texels", "3");
    await page.click("#compact");
    await ed(() => window.scafEditor.when(() => window.scafEditor.idle() && window.scafEditor.state().padding !== 4 / 1024 || window.scafEditor.error));
    const err = await ed(() => window.scafEditor.error);
    if (err) fail("compact at 3 texels: " + err);
    if ((await apiState()).padding !== 3 / 1024) fail("padding after compact: " + (await apiState()).padding);
    await page.click("#save");
    await ed(() => window.scafEditor.when(() => window.scafEditor.saved || window.scafEditor.error));
    if (await ed(() => window.scafEditor.error)) fail("save: " + await ed(() => window.scafEditor.error));
    const check = spawnSync(scaf, ["check", saved], { encoding: "utf8" });
    if (check.status !== 0) fail(`scaf check ${saved}: exit ${check.status}\n${check.stdout}`);
    const gap = Number((/min chart gap\s+(\S+)/.exec(check.stdout) || [])[1]);
    console.log(`saved at padding 3/1024: min chart gap ${gap}`);
    if (!(gap >= 3 / 1024)) fail(`saved: min chart gap ${gap} below 3/1024`);
  }

  await page.screenshot({ path: path.join(work, "scaf-edit-padding.png") });
  if (errors.length) fail("page errors: " + errors.join("; "));
  console.log(`scaf edit tools in ${await browser.version()}: texture, 3D view, selection, pins, padding; screenshots in ${work}`);
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
  }
  rmSync(autosave, { force: true });
  if (existsSync(saved) && process.exitCode) console.error("(the saved file stays: " + saved + ")");
}
