// tools/edit_page_tools.js: the second script of `scaf edit`'s page
// (tools/edit_page.html loads it from the server, which has it compiled in
// by cmake/embed_file.cmake): selection of islands and vertices, pins, the
// image under the UVs (checker or --texture), the linked 3D view (three.js,
// also compiled in) and the padding of compact.
//
// It runs in the page's global scope after the page's own script and uses
// its globals (mesh, state, view, ctx, canvas, api, take, draw, setStatus,
// toCanvas, toUV, faceAt, answered, spaceHeld, drag, inFlight). The page
// calls back through window.scafTools: under(ctx) before the charts are
// filled, faceAlpha() for their fill, over(ctx) after everything, took(s)
// after each new state, compactBody() for the compact request. What the
// tests read is added to window.scafEditor (selection(), pins, hovered,
// view3d, ...); the drag code of the page reads the selection there too.
"use strict";
(() => {
  const editor = window.scafEditor;
  const el = id => document.getElementById(id);

  // ---- the controls: one group in the bar, the 3D panel in the stage --------
  const style = document.createElement("style");
  style.textContent = `
    #tools { display: contents; }
    #tools .group { display: inline-flex; gap: 6px; align-items: center; }
    #padding-texels { width: 4.5em; }
    #padding-texels.bad { background: #fdd; }
    #stage.with3d #view { width: 60%; }
    #stage.with3d #legend { right: calc(40% + 12px); }
    #view3d { position: absolute; right: 0; top: 0; width: 40%; height: 100%; border-left: 1px solid #bbb;
              background: #eef0f3; display: none; }
    #stage.with3d #view3d { display: block; }
    #view3d canvas { display: block; width: 100%; height: 100%; cursor: grab; touch-action: none; }
    #view3d-note { position: absolute; left: 10px; top: 10px; right: 10px; color: #555; font-size: 13px; }
    #view3d-note.error { color: #b00; }
    #box { position: absolute; border: 1px dashed #e06c00; background: rgba(255,140,0,.08); pointer-events: none; display: none; }
  `;
  document.head.appendChild(style);
  const group = document.createElement("span");
  group.id = "tools";
  group.innerHTML = `
    <span class="group" title="what a click or a box selects (Tab switches); shift-click adds or removes, a drag on empty space or ctrl + drag draws a box, Escape clears">
      <span class="mode">select:</span>
      <label><input type="radio" name="selmode" value="island" checked> islands</label>
      <label><input type="radio" name="selmode" value="vertex"> vertices</label>
      <span id="selcount">none</span></span>
    <button id="pin" title="pin the selected vertices (P): they never move">pin</button>
    <button id="unpin" title="unpin the selected vertices (U)">unpin</button>
    <label title="the image under the layout, in the unit square the save normalizes into, and on the 3D view">image
      <select id="image"><option value="checker">checker</option><option value="texture">texture</option></select></label>
    <label><input type="checkbox" id="underlay"> under the UVs</label>
    <label><input type="checkbox" id="show3d" checked> 3D view</label>
    <label title="the smallest gap compact keeps between two charts, in texels of the resolution (the padding of every later drag and save; larger than the layout keeps now is refused)">padding
      <input type="number" id="padding-texels" min="0.001" step="any"> texels</label>`;
  el("bar").insertBefore(group, el("unsaved"));
  const panel = document.createElement("div");
  panel.id = "view3d";
  panel.innerHTML = `<canvas id="canvas3d"></canvas><div id="view3d-note">loading the 3D view…</div>`;
  el("stage").appendChild(panel);
  const box = document.createElement("div");
  box.id = "box";
  el("stage").appendChild(box);
  el("stage").classList.add("with3d");

  // ---- selection -------------------------------------------------------------
  const selected = { charts: new Set(), vertices: new Set() };
  let hovered = -1;      // the chart under the pointer, in either view (-1: none)
  let boxing = null;     // the box selection in progress
  let pinned = new Set();
  let boundary = null;   // per chart: its boundary edges (layout vertex pairs)
  let vertexChart = null;
  const selMode = () => document.querySelector("input[name=selmode]:checked").value;

  function buildTopology() {
    const F = mesh.faces, C = mesh.face_chart, count = new Map();
    vertexChart = new Int32Array(mesh.nuv).fill(-1);
    for (let f = 0; f < C.length; f++)
      for (let k = 0; k < 3; k++) {
        const a = F[3 * f + k], b = F[3 * f + (k + 1) % 3];
        vertexChart[a] = C[f];
        const key = a < b ? a + "," + b : b + "," + a;
        const e = count.get(key);
        if (e) e.n++; else count.set(key, { a, b, chart: C[f], n: 1 });
      }
    boundary = Array.from({ length: mesh.ncharts }, () => []);
    for (const e of count.values()) if (e.n === 1) boundary[e.chart].push(e.a, e.b);
  }

  function selectionChanged() {
    const c = selected.charts.size, v = selected.vertices.size;
    el("selcount").textContent = c + v === 0 ? "none"
      : (c ? c + (c === 1 ? " island" : " islands") : "") + (c && v ? ", " : "") + (v ? v + (v === 1 ? " vertex" : " vertices") : "");
    el("pin").disabled = el("unpin").disabled = v === 0;
    editor.selectionChanges++;
    draw();
    paint3d();
    setTimeout(answered, 0);
  }
  function clearSelection() {
    selected.charts.clear();
    selected.vertices.clear();
    selectionChanged();
  }
  function toggle(set, x, add) {
    if (!add) { set.clear(); set.add(x); } else if (set.has(x)) set.delete(x); else set.add(x);
  }

  // the layout vertex nearest canvas pixel (x, y), within 10 CSS pixels (-1: none)
  function vertexAt(x, y) {
    const uv = state.uv, dpr = window.devicePixelRatio || 1, reach = 10 * dpr;
    let best = -1, bd = reach * reach;
    for (let i = 0; i < uv.length / 2; i++) {
      const p = toCanvas(uv[2 * i], uv[2 * i + 1]), d = (p[0] - x) ** 2 + (p[1] - y) ** 2;
      if (d <= bd) { bd = d; best = i; }
    }
    return best;
  }
  function canvasPoint(ev) {
    const r = canvas.getBoundingClientRect(), dpr = canvas.width / r.width;
    return [(ev.clientX - r.left) * dpr, (ev.clientY - r.top) * dpr];
  }

  // A box selects what lies in it: islands with a vertex inside, or vertices.
  function boxSelect(b) {
    const [u0, v1] = toUV(Math.min(b.x0, b.x1), Math.min(b.y0, b.y1));
    const [u1, v0] = toUV(Math.max(b.x0, b.x1), Math.max(b.y0, b.y1));
    const uv = state.uv, island = b.mode === "island";
    if (!b.add) (island ? selected.charts : selected.vertices).clear();
    for (let i = 0; i < uv.length / 2; i++)
      if (uv[2 * i] >= u0 && uv[2 * i] <= u1 && uv[2 * i + 1] >= v0 && uv[2 * i + 1] <= v1) {
        if (island) selected.charts.add(vertexChart[i]); else selected.vertices.add(i);
      }
    selectionChanged();
  }

  // Before the page's drag code (capture on the stage): selection clicks
  // and boxes. A click on an island selects it and lets the drag go on (a
  // selected island keeps a multi-selection); shift-click toggles and
  // drags nothing; vertex mode selects (alt still drags a vertex).
  el("stage").addEventListener("pointerdown", ev => {
    if (ev.target !== canvas || !state || !boundary || drag || ev.button !== 0 || spaceHeld || ev.altKey) return;
    const [x, y] = canvasPoint(ev), m = selMode();
    const f = faceAt(...toUV(x, y)), add = ev.shiftKey;
    const boxIt = ev.ctrlKey || ev.metaKey || m === "vertex" || f < 0;
    if (!boxIt) {
      const c = mesh.face_chart[f];
      if (add) {
        toggle(selected.charts, c, true);
        selectionChanged();
        ev.stopImmediatePropagation();
        ev.preventDefault();
      } else if (!selected.charts.has(c)) {
        toggle(selected.charts, c, false);
        selected.vertices.clear();
        selectionChanged();
      }
      return;  // the page's drag starts
    }
    ev.stopImmediatePropagation();
    ev.preventDefault();
    canvas.setPointerCapture(ev.pointerId);
    boxing = { x0: x, y0: y, x1: x, y1: y, add, mode: m, id: ev.pointerId, vertex: m === "vertex" ? vertexAt(x, y) : -1 };
  }, true);
  canvas.addEventListener("pointermove", ev => {
    if (boxing && ev.pointerId === boxing.id) {
      [boxing.x1, boxing.y1] = canvasPoint(ev);
      const r = canvas.getBoundingClientRect(), dpr = canvas.width / r.width, s = el("stage").getBoundingClientRect();
      Object.assign(box.style, {
        display: "block", left: (r.left - s.left + Math.min(boxing.x0, boxing.x1) / dpr) + "px",
        top: (r.top - s.top + Math.min(boxing.y0, boxing.y1) / dpr) + "px",
        width: Math.abs(boxing.x1 - boxing.x0) / dpr + "px", height: Math.abs(boxing.y1 - boxing.y0) / dpr + "px"
      });
      return;
    }
    if (drag || !state || !boundary) return;
    const f = faceAt(...toUV(...canvasPoint(ev)));
    setHovered(f < 0 ? -1 : mesh.face_chart[f]);
  });
  canvas.addEventListener("pointerleave", () => { if (!drag) setHovered(-1); });
  const endBox = ev => {
    if (!boxing || ev.pointerId !== boxing.id) return;
    const b = boxing, dpr = window.devicePixelRatio || 1;
    boxing = null;
    box.style.display = "none";
    if (Math.hypot(b.x1 - b.x0, b.y1 - b.y0) >= 3 * dpr) { boxSelect(b); return; }
    // a click: a vertex (vertex mode), else nothing there clears
    if (b.mode === "vertex" && b.vertex >= 0) {
      toggle(selected.vertices, b.vertex, b.add);
      if (!b.add) selected.charts.clear();
      selectionChanged();
    } else if (b.mode === "island") {
      const f = faceAt(...toUV(b.x0, b.y0));
      if (f >= 0) toggle(selected.charts, mesh.face_chart[f], b.add);
      else if (!b.add) selected.charts.clear();
      selectionChanged();
    } else if (!b.add) clearSelection();
  };
  canvas.addEventListener("pointerup", endBox);
  canvas.addEventListener("pointercancel", endBox);

  function setHovered(c) {
    if (c === hovered) return;
    hovered = c;
    editor.hoverChanges++;
    draw();
    paint3d();
    setTimeout(answered, 0);
  }

  // ---- pins ------------------------------------------------------------------
  // One request per vertex (the API pins one); the state of the last one.
  async function pinSelected(on) {
    if (drag || inFlight || !selected.vertices.size) return;
    const todo = [...selected.vertices].filter(i => pinned.has(i) !== on);
    setStatus((on ? "pinning " : "unpinning ") + todo.length + " vertices…");
    try {
      let s = null;
      for (const i of todo) s = await api("POST", "/api/pin", { vertex: i, pinned: on ? 1 : 0 });
      if (s) take(s);
      setStatus((on ? "pinned " : "unpinned ") + todo.length + " vertices; " + pinned.size + " pinned in all");
    } catch (e) {
      setStatus((on ? "pin: " : "unpin: ") + e.message, true);
    }
  }
  el("pin").addEventListener("click", () => pinSelected(true));
  el("unpin").addEventListener("click", () => pinSelected(false));

  // ---- keys: Escape, P, U, Tab -------------------------------------------------
  window.addEventListener("keydown", ev => {
    const t = ev.target;
    if (t && t.tagName === "INPUT" && (t.type === "number" || t.type === "text")) return;
    if (ev.ctrlKey || ev.metaKey || ev.altKey) return;
    const key = ev.key.length === 1 ? ev.key.toLowerCase() : ev.key;
    if (key === "Escape") clearSelection();
    else if (key === "p") pinSelected(true);
    else if (key === "u") pinSelected(false);
    else if (key === "Tab") {
      const other = selMode() === "island" ? "vertex" : "island";
      document.querySelector(`input[name=selmode][value=${other}]`).checked = true;
    } else return;
    ev.preventDefault();
  }, true);

  // ---- the image: the checker, or the --texture PNG --------------------------
  let textureImage = null;  // the decoded --texture image (null: none or not yet)
  const checkerImage = (() => {
    const c = document.createElement("canvas"), n = 16, px = 32;
    c.width = c.height = n * px;
    const g = c.getContext("2d");
    for (let i = 0; i < n; i++) for (let j = 0; j < n; j++) {
      // light and dark squares, a little redder along u and bluer along v
      // (row 0 is the top: v = 1): the orientation shows
      const l = (i + j) % 2 ? 232 : 110, r = l + Math.round(22 * i / n), b = l + Math.round(22 * (n - 1 - j) / n);
      g.fillStyle = `rgb(${Math.min(255, r)},${l},${Math.min(255, b)})`;
      g.fillRect(i * px, j * px, px, px);
    }
    return c;
  })();
  const imageChoice = () => el("image").value === "texture" && textureImage ? "texture" : "checker";
  const currentImage = () => imageChoice() === "texture" ? textureImage : checkerImage;
  el("image").addEventListener("change", () => { draw(); retexture3d(); });
  el("underlay").addEventListener("change", draw);

  // ---- the padding field: texels of the resolution ---------------------------
  const resolutionNow = () => {
    const r = Math.round(Number(el("resolution").value));
    return r >= 1 && r <= 65536 ? r : 1024;
  };
  function showPadding() {
    el("padding-texels").value = Number((mesh.padding * resolutionNow()).toPrecision(6));
    el("padding-texels").title = "padding " + mesh.padding.toPrecision(6) + " of the unit square";
    el("padding-texels").classList.remove("bad");
  }
  // the padding compact should keep (unit square), or null when the field is bad
  function paddingWanted() {
    const t = Number(el("padding-texels").value), p = t / resolutionNow();
    const ok = el("padding-texels").value !== "" && isFinite(p) && p >= Math.pow(2, -200) && p < 0.5;
    el("padding-texels").classList.toggle("bad", !ok);
    return ok ? p : null;
  }
  el("padding-texels").addEventListener("input", paddingWanted);
  el("resolution").addEventListener("input", showPadding);

  // ---- the hooks the page calls ---------------------------------------------
  window.scafTools = {
    under(g) {  // the image in the unit square, under the charts
      if (!el("underlay").checked || !state) return;
      const fr = unitFrame(), [xa, ya] = toCanvas(fr.u, fr.v + fr.side), [xb, yb] = toCanvas(fr.u + fr.side, fr.v);
      g.imageSmoothingEnabled = true;
      g.drawImage(currentImage(), xa, ya, xb - xa, yb - ya);
      editor.underlays++;
    },
    faceAlpha: () => el("underlay").checked ? 0.45 : 1,
    over(g) {  // selection, hover, pins
      if (!state || !boundary) return;
      const uv = state.uv, dpr = window.devicePixelRatio || 1;
      const outline = (c, colour, width) => {
        const E = boundary[c];
        g.beginPath();
        for (let k = 0; k < E.length; k += 2) {
          const a = toCanvas(uv[2 * E[k]], uv[2 * E[k] + 1]), b = toCanvas(uv[2 * E[k + 1]], uv[2 * E[k + 1] + 1]);
          g.moveTo(a[0], a[1]); g.lineTo(b[0], b[1]);
        }
        g.strokeStyle = colour; g.lineWidth = width * dpr; g.stroke();
      };
      g.lineCap = "round";
      for (const c of selected.charts) outline(c, "#e06c00", 3);
      if (hovered >= 0) outline(hovered, selected.charts.has(hovered) ? "#7a2f00" : "#1d4ed8", 2);
      for (const i of pinned) {  // a pin: a dark red disc ringed in white
        const p = toCanvas(uv[2 * i], uv[2 * i + 1]);
        g.beginPath(); g.arc(p[0], p[1], 4.5 * dpr, 0, 2 * Math.PI);
        g.fillStyle = "#a00018"; g.fill();
        g.strokeStyle = "#fff"; g.lineWidth = 1.5 * dpr; g.stroke();
      }
      for (const i of selected.vertices) {  // a selected vertex: an orange square (around its pin)
        const p = toCanvas(uv[2 * i], uv[2 * i + 1]), h = (pinned.has(i) ? 7 : 4) * dpr;
        g.strokeStyle = "#fff"; g.lineWidth = 4 * dpr;
        g.strokeRect(p[0] - h, p[1] - h, 2 * h, 2 * h);
        g.strokeStyle = "#e06c00"; g.lineWidth = 2 * dpr;
        g.strokeRect(p[0] - h, p[1] - h, 2 * h, 2 * h);
        if (!pinned.has(i)) { g.fillStyle = "#e06c00"; g.fillRect(p[0] - h / 2, p[1] - h / 2, h, h); }
      }
    },
    took(s) {
      pinned = new Set(s.pinned_vertices || []);
      if (typeof s.padding === "number" && mesh && s.padding !== mesh.padding) {
        mesh.padding = s.padding;
        showPadding();
      }
      update3d();
    },
    compactBody() {
      const p = paddingWanted();
      if (p === null) throw new Error("the padding must be more than 0 texels and less than half the resolution");
      return p === mesh.padding ? {} : { padding: p };
    }
  };

  // ---- what the tests (and the drag code) read ------------------------------
  Object.assign(editor, {
    toolsReady: false, selectionChanges: 0, hoverChanges: 0, underlays: 0,
    selection: () => ({ charts: [...selected.charts].sort((a, b) => a - b),
                        vertices: [...selected.vertices].sort((a, b) => a - b) }),
    selectMode: () => selMode(),
    pinned: () => [...pinned].sort((a, b) => a - b),
    hovered: () => hovered,
    texture: () => ({ given: !!(mesh && mesh.texture), loaded: !!textureImage,
                      width: textureImage ? textureImage.naturalWidth : 0, height: textureImage ? textureImage.naturalHeight : 0,
                      shown: imageChoice(), under: el("underlay").checked }),
    view3d: () => ({ ready: !!three, renders: renders, note: el("view3d-note").textContent, hovered: hovered }),
    // what the 3D canvas shows now: pixels unlike its background, colours
    pixels3d: () => three ? readPixels() : null,
    // the page point of a 3D surface point of face f's centroid (CSS pixels), or null when hidden
    facePoint3d: f => three ? projectFace(f) : null
  });

  // ---- the 3D view -------------------------------------------------------------
  let three = null;  // { renderer, scene, camera, geometry, ... } once running
  let renders = 0;
  const canvas3d = el("canvas3d"), note = el("view3d-note");
  function say3d(text, isError) {
    note.textContent = text;
    note.className = isError ? "error" : "";
    note.hidden = !text;
  }
  el("show3d").addEventListener("change", () => {
    el("stage").classList.toggle("with3d", el("show3d").checked);
    resize3d();
  });

  function start3d() {
    if (!mesh.three) {
      say3d("3D view unavailable: this scaf was built without three.js (Debian's libjs-three was not " +
            "installed at build time; scripts/setup.sh installs it).", true);
      editor.toolsReady = true;
      return;
    }
    const s = document.createElement("script");
    s.src = "/three.min.js?token=" + encodeURIComponent(token);
    s.onload = () => {
      try { build3d(); } catch (e) { say3d("3D view unavailable: " + e.message, true); }
      editor.toolsReady = true;
      setTimeout(answered, 0);
    };
    s.onerror = () => {
      say3d("3D view unavailable: three.js did not load from the server.", true);
      editor.toolsReady = true;
      setTimeout(answered, 0);
    };
    document.head.appendChild(s);
  }

  function build3d() {
    const THREE = window.THREE;
    let renderer;
    try {
      renderer = new THREE.WebGLRenderer({ canvas: canvas3d, antialias: true, preserveDrawingBuffer: true });
    } catch (e) {
      throw new Error("this browser gives no WebGL (" + e.message + ")");
    }
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xeef0f3, 1);
    const F = mesh.faces3d, X = mesh.xyz, nf = F.length / 3;
    const pos = new Float32Array(9 * nf), col = new Float32Array(9 * nf).fill(1);
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (let f = 0; f < nf; f++) for (let k = 0; k < 3; k++) for (let c = 0; c < 3; c++) {
      const x = X[3 * F[3 * f + k] + c];
      pos[9 * f + 3 * k + c] = x;
      lo[c] = Math.min(lo[c], x); hi[c] = Math.max(hi[c], x);
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(pos, 3));
    geometry.setAttribute("uv", new THREE.BufferAttribute(new Float32Array(6 * nf), 2));
    geometry.setAttribute("color", new THREE.BufferAttribute(col, 3));
    geometry.computeVertexNormals();
    const texture = new THREE.CanvasTexture(checkerImage);
    texture.anisotropy = 4;
    const material = new THREE.MeshLambertMaterial({ map: texture, vertexColors: THREE.VertexColors, side: THREE.DoubleSide });
    const object = new THREE.Mesh(geometry, material);
    const scene = new THREE.Scene();
    scene.add(object);
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    const camera = new THREE.PerspectiveCamera(35, 1, 1e-3, 1e3);
    const light = new THREE.DirectionalLight(0xffffff, 0.6);
    camera.add(light);
    scene.add(camera);
    const centre = new THREE.Vector3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    const radius = Math.max(1e-9, Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2);
    camera.near = radius / 100; camera.far = radius * 100;
    three = { THREE, renderer, scene, camera, geometry, object, material, texture, centre, radius,
              orbit: { theta: 0.6, phi: 1.1, distance: 3.2 * radius }, raycaster: new THREE.Raycaster() };
    say3d("");
    retexture3d();
    update3d();
    resize3d();
    new ResizeObserver(resize3d).observe(canvas3d);
    orbitControls();
  }

  function placeCamera() {
    const o = three.orbit, c = three.centre, cam = three.camera;
    cam.position.set(c.x + o.distance * Math.sin(o.phi) * Math.sin(o.theta), c.y + o.distance * Math.cos(o.phi),
                     c.z + o.distance * Math.sin(o.phi) * Math.cos(o.theta));
    cam.lookAt(c);
  }
  function render3d() {
    if (!three) return;
    placeCamera();
    three.renderer.render(three.scene, three.camera);
    renders++;
    setTimeout(answered, 0);
  }
  function resize3d() {
    if (!three) return;
    const r = canvas3d.getBoundingClientRect();
    if (r.width < 1 || r.height < 1) return;
    three.renderer.setSize(r.width, r.height, false);
    three.camera.aspect = r.width / r.height;
    three.camera.updateProjectionMatrix();
    render3d();
  }
  // the current UVs, normalized into the unit square as the save does
  function update3d() {
    if (!three || !state) return;
    const fr = unitFrame(), F = mesh.faces, uv = state.uv, a = three.geometry.attributes.uv.array;
    for (let k = 0; k < F.length; k++) {
      a[2 * k] = (uv[2 * F[k]] - fr.u) / fr.side;
      a[2 * k + 1] = (uv[2 * F[k] + 1] - fr.v) / fr.side;
    }
    three.geometry.attributes.uv.needsUpdate = true;
    render3d();
  }
  // vertex colours: the hovered island lit, the selected ones tinted
  function paint3d() {
    if (!three) return;
    const C = mesh.face_chart, a = three.geometry.attributes.color.array;
    for (let f = 0; f < C.length; f++) {
      const rgb = C[f] === hovered ? [1, 0.62, 0.25] : selected.charts.has(C[f]) ? [1, 0.85, 0.65] : [1, 1, 1];
      for (let k = 0; k < 3; k++) a.set(rgb, 9 * f + 3 * k);
    }
    three.geometry.attributes.color.needsUpdate = true;
    render3d();
  }
  function retexture3d() {
    if (!three) return;
    three.texture.dispose();
    three.texture = imageChoice() === "texture" ? new three.THREE.Texture(textureImage) : new three.THREE.CanvasTexture(checkerImage);
    three.texture.needsUpdate = true;
    three.texture.anisotropy = 4;
    three.material.map = three.texture;
    three.material.needsUpdate = true;
    render3d();
  }

  // the chart under a point of the 3D canvas (-1: none)
  function chartAt3d(ev) {
    const r = canvas3d.getBoundingClientRect();
    const p = new three.THREE.Vector2(((ev.clientX - r.left) / r.width) * 2 - 1, -((ev.clientY - r.top) / r.height) * 2 + 1);
    three.raycaster.setFromCamera(p, three.camera);
    const hit = three.raycaster.intersectObject(three.object)[0];
    return hit ? mesh.face_chart[hit.faceIndex] : -1;
  }
  function orbitControls() {
    let grab = null;
    canvas3d.addEventListener("pointerdown", ev => {
      canvas3d.setPointerCapture(ev.pointerId);
      grab = { x: ev.clientX, y: ev.clientY, id: ev.pointerId };
      canvas3d.style.cursor = "grabbing";
    });
    canvas3d.addEventListener("pointermove", ev => {
      if (grab && ev.pointerId === grab.id) {
        const o = three.orbit;
        o.theta -= (ev.clientX - grab.x) * 0.01;
        o.phi = Math.min(Math.PI - 0.01, Math.max(0.01, o.phi - (ev.clientY - grab.y) * 0.01));
        grab.x = ev.clientX; grab.y = ev.clientY;
        editor.orbits++;
        render3d();
        return;
      }
      setHovered(chartAt3d(ev));
    });
    const end = ev => { if (grab && ev.pointerId === grab.id) { grab = null; canvas3d.style.cursor = "grab"; } };
    canvas3d.addEventListener("pointerup", end);
    canvas3d.addEventListener("pointercancel", end);
    canvas3d.addEventListener("pointerleave", () => { if (!grab) setHovered(-1); });
    canvas3d.addEventListener("wheel", ev => {
      ev.preventDefault();
      const unit = ev.deltaMode === 1 ? 33 : ev.deltaMode === 2 ? 400 : 1;
      const o = three.orbit;
      o.distance = Math.min(50 * three.radius, Math.max(0.2 * three.radius, o.distance * Math.pow(1.25, ev.deltaY * unit / 100)));
      render3d();
    }, { passive: false });
  }
  editor.orbits = 0;

  function readPixels() {
    const gl = three.renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const px = new Uint8Array(4 * w * h);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
    let other = 0, sum = 0;
    const colours = new Set();
    for (let i = 0; i < px.length; i += 4) {
      sum = (sum * 31 + px[i] + 7 * px[i + 1] + 13 * px[i + 2]) % 1000000007;  // a checksum of the picture
      if (Math.abs(px[i] - 0xee) + Math.abs(px[i + 1] - 0xf0) + Math.abs(px[i + 2] - 0xf3) > 6) other++;
      colours.add((px[i] >> 3) << 10 | (px[i + 1] >> 3) << 5 | (px[i + 2] >> 3));
    }
    return { width: w, height: h, other, colours: colours.size, sum };
  }
  function projectFace(f) {
    const F = mesh.faces3d, X = mesh.xyz, v = new three.THREE.Vector3();
    for (let k = 0; k < 3; k++) v.add(new three.THREE.Vector3(X[3 * F[3 * f + k]], X[3 * F[3 * f + k] + 1], X[3 * F[3 * f + k] + 2]));
    v.multiplyScalar(1 / 3);
    placeCamera();
    three.camera.updateMatrixWorld();
    v.project(three.camera);
    const r = canvas3d.getBoundingClientRect();
    return [r.left + (v.x + 1) / 2 * r.width, r.top + (1 - v.y) / 2 * r.height, v.z];
  }

  // ---- start: once the page has its mesh ----------------------------------------
  editor.when(() => editor.ready || editor.error).then(() => {
    if (!editor.ready) return;
    buildTopology();
    showPadding();
    pinned = new Set(state.pinned_vertices || []);
    selectionChanged();
    if (mesh.texture) {
      const img = new Image();
      img.onload = () => {
        textureImage = img;
        el("image").value = "texture";
        el("underlay").checked = true;
        editor.textureLoads++;
        draw();
        retexture3d();
        setTimeout(answered, 0);
      };
      img.onerror = () => { setStatus("--texture " + mesh.texture + ": the browser cannot decode it", true); };
      img.src = "/texture.png?token=" + encodeURIComponent(token);
    } else {
      el("image").querySelector("option[value=texture]").disabled = true;
      el("image").title = "no --texture given: the checker";
    }
    start3d();
    draw();
    setTimeout(answered, 0);
  });
  editor.textureLoads = 0;
})();
