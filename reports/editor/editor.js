// crossdiv's curve editor: add, remove and drag the control points of Bezier chains, B-splines
// and Catmull-Rom splines in 2D and in 3D, see each curve, its uniform tessellation and the de
// Casteljau construction at a chosen t, and export the SWP file `crossdiv tessellate` reads.
//
// The page opens from disk, offline: three.js and OrbitControls are Debian's (libjs-three), copied
// beside it; spline_math.js has the arithmetic. The curves come from window.CROSSDIV_EDITOR_DATA
// (written by `crossdiv editor`, or by the report for its curves page, which adds core's adaptive
// tessellations and frames of each file curve), else a small example. window.crossdivEditor is
// the page's state and drawing functions, for the browser tests and the curious.
(function () {
  "use strict";

  const S = window.CrossdivSplines;
  const data = Object.assign({title: "Curve editor"}, window.CROSSDIV_EDITOR_DATA);
  if (!data.curves)  // an empty start: one small Bezier segment to drag
    data.curves = [{name: "first", keyword: "bez2", steps: 16, points: [[0, 0, 0], [1, 2, 0], [3, 2, 0], [4, 0, 0]]}];
  const PICK_PIXELS = 9;     // a point is under the mouse within this many pixels
  const CLICK_PIXELS = 3;    // a press that moves less than this is a click, not a drag
  const BACKGROUND = 0x1e2226;

  const state = {
    curves: data.curves.map((c) => ({name: c.name, keyword: c.keyword, steps: c.steps,
                                     points: c.points.map((p) => [p[0], p[1], p[2] || 0]), core: c.core || null,
                                     edited: false})),
    selected: 0,       // curve index
    point: -1,         // selected control point of that curve
    t: 0.5,            // along the selected curve, in [0, 1] of its parameter range
    mode3d: data.curves.some((c) => S.dimOf(c.keyword) === 3),
    solo: !!data.solo,  // draw the selected curve alone, framed, in its own dimension
  };
  if (state.solo && state.curves.length) state.mode3d = S.dimOf(state.curves[0].keyword) === 3;

  const view = document.getElementById("view");
  const renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
  renderer.setPixelRatio(1);
  renderer.setClearColor(BACKGROUND);
  view.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  const drawn = new THREE.Group();
  scene.add(drawn);
  let camera = null, controls = null;

  // ---- views: an orthographic top view in 2D, a perspective orbit with z up in 3D.
  /// The curves drawn: all, or the selected one alone (the report's page of many files).
  function shown() {
    return state.solo ? state.curves.filter((c, i) => i === state.selected) : state.curves;
  }

  function bounds() {
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (const c of shown())
      for (const p of c.points)
        for (let k = 0; k < 3; ++k) { lo[k] = Math.min(lo[k], p[k]); hi[k] = Math.max(hi[k], p[k]); }
    if (!isFinite(lo[0])) return {centre: [0, 0, 0], size: 4};
    return {centre: lo.map((l, k) => (l + hi[k]) / 2), size: Math.max(1, hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2])};
  }

  function makeCamera() {
    const w = view.clientWidth, h = view.clientHeight, b = bounds(), r = 0.75 * b.size;
    if (controls) controls.dispose();
    if (state.mode3d) {
      camera = new THREE.PerspectiveCamera(40, w / h, b.size / 100, b.size * 100);
      camera.up.set(0, 0, 1);
      camera.position.set(b.centre[0] + 1.6 * b.size, b.centre[1] - 2.2 * b.size, b.centre[2] + 1.4 * b.size);
    } else {
      const aspect = w / h;
      camera = new THREE.OrthographicCamera(-r * aspect, r * aspect, r, -r, -100 * b.size, 100 * b.size);
      camera.position.set(b.centre[0], b.centre[1], 10 * b.size);
    }
    controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.target.set(b.centre[0], b.centre[1], state.mode3d ? b.centre[2] : 0);
    controls.enableRotate = state.mode3d;
    controls.screenSpacePanning = true;
    if (!state.mode3d) controls.mouseButtons = {LEFT: THREE.MOUSE.PAN, MIDDLE: THREE.MOUSE.DOLLY, RIGHT: THREE.MOUSE.PAN};
    controls.update();
    controls.addEventListener("change", render);
    document.getElementById("toggle-3d").textContent = state.mode3d ? "2D view" : "3D view";
  }

  function resize() {
    renderer.setSize(view.clientWidth, view.clientHeight);
    makeCamera();
    redraw();
  }

  // ---- drawing
  function line(points, color, opts) {
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.Float32BufferAttribute(points.flat(), 3));
    const m = opts && opts.dashed ? new THREE.LineDashedMaterial({color, dashSize: 0.06 * bounds().size, gapSize: 0.04 * bounds().size})
                                  : new THREE.LineBasicMaterial({color});
    const l = opts && opts.segments ? new THREE.LineSegments(g, m) : new THREE.Line(g, m);
    if (opts && opts.dashed) l.computeLineDistances();
    return l;
  }

  function dots(points, color, size) {
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.Float32BufferAttribute(points.flat(), 3));
    return new THREE.Points(g, new THREE.PointsMaterial({color, size, sizeAttenuation: false}));
  }

  function selectedCurve() { return state.curves[state.selected]; }

  /// The selected curve's segment and local t at the slider: {segment, t, control}.
  function casteljauAt(curve, tGlobal) {
    const segs = S.segments(curve);
    if (!segs.length) return null;
    const u = tGlobal * segs.length, k = Math.min(Math.floor(u), segs.length - 1);
    return {segment: k, t: u - k, control: segs[k]};
  }

  function redraw() {
    drawn.clear ? drawn.clear() : drawn.children.slice().forEach((c) => drawn.remove(c));
    if (state.mode3d) {
      const b = bounds(), grid = new THREE.GridHelper(2 * b.size, 16, 0x505860, 0x353b42);
      grid.rotation.x = Math.PI / 2;  // GridHelper lies in xz; the ground is z = 0
      grid.position.set(b.centre[0], b.centre[1], 0);
      drawn.add(grid);
    }
    state.curves.forEach((c, i) => {
      if (state.solo && i !== state.selected) return;
      const type = S.TYPES[S.stem(c.keyword)], mine = i === state.selected;
      if (document.getElementById("show-polygon").checked && c.points.length)
        drawn.add(line(S.stem(c.keyword) === "crc" ? c.points.concat([c.points[0]]) : c.points, type.color, {dashed: true}));
      if (c.points.length) drawn.add(dots(c.points, type.color, mine ? 9 : 6));
      const tess = S.tessellate(c);
      if (tess.points.length) drawn.add(line(tess.points, mine ? 0xffffff : 0xb0b0b0));
      if (mine && document.getElementById("show-samples").checked && tess.points.length)
        drawn.add(dots(tess.points, 0xffffff, 3));
    });
    const c = selectedCurve();
    if (c && state.point >= 0 && state.point < c.points.length) drawn.add(dots([c.points[state.point]], 0xff3030, 13));
    if (c && document.getElementById("show-casteljau").checked) {
      const at = casteljauAt(c, state.t);
      if (at) {
        const levels = S.casteljau(at.control, at.t), colors = [0x909090, 0x40a0ff, 0x40e040, 0xff4040];
        levels.forEach((lv, k) => {
          if (k > 0 && lv.length > 1) drawn.add(line(lv, colors[k % colors.length]));
          if (k > 0) drawn.add(dots(lv, colors[Math.min(k, colors.length - 1)], k === levels.length - 1 ? 11 : 6));
        });
      }
    }
    if (c) drawCore(c);
    render();
    describe();
  }

  function render() { renderer.render(scene, camera); }

  // ---- core's adaptive tessellations and frames (the report's curves page)
  let coreFor = null;  // the curve the run and frame lists were filled for
  function drawCore(c) {
    const box = document.getElementById("core");
    box.style.display = c.core ? "" : "none";
    if (!c.core) return;
    if (coreFor !== c) fillCoreControls(c);
    coreFor = c;
    const note = document.getElementById("core-note");
    if (c.edited) {
      note.textContent = "core's tessellations and frames are of the file's curve; this one was edited, so they are hidden.";
      return;
    }
    note.textContent = "";
    const run = c.core.tessellations[Number(document.getElementById("core-run").value)];
    if (run) {
      drawn.add(line(run.points, 0xffa040));
      drawn.add(dots(run.points, 0xffa040, 5));
      drawn.add(dots([run.worst], 0xff2020, 12));
    }
    const frames = document.getElementById("core-frames").value, f = frames && c.core.frames[frames];
    if (f) {
      const len = 0.05 * bounds().size, T = [], N = [], B = [];
      f.points.forEach((p, i) => {
        const seg = (v, out) => out.push(p, [p[0] + len * v[i][0], p[1] + len * v[i][1], p[2] + len * v[i][2]]);
        seg(f.T, T); seg(f.N, N); seg(f.B, B);
      });
      // The seed's colours: N red, B green, T blue.
      drawn.add(line(N, 0xff4040, {segments: true}));
      drawn.add(line(B, 0x40e040, {segments: true}));
      drawn.add(line(T, 0x4080ff, {segments: true}));
    }
  }

  function fillCoreControls(c) {
    if (!c.core) return;
    const runs = document.getElementById("core-run"), keep = runs.value;
    runs.innerHTML = "";
    c.core.tessellations.forEach((r, i) => runs.add(new Option(`${r.mode} ${r.tol.toPrecision(2)}: ${r.edges} edges`, String(i))));
    runs.add(new Option("none", ""));
    if (keep !== "" && Number(keep) < c.core.tessellations.length) runs.value = keep;
    const frames = document.getElementById("core-frames"), keepFrames = frames.value;
    frames.innerHTML = "";
    for (const f of [""].concat(Object.keys(c.core.frames))) frames.add(new Option(f || "none", f));
    frames.value = keepFrames in c.core.frames ? keepFrames : "";
    // Distances of every run; the worst point is marked red on the curve.
    document.getElementById("core-table").innerHTML =
      "<tr><th>mode</th><th>tolerance</th><th>edges</th><th>measured deviation</th></tr>" +
      c.core.tessellations.map((r) => `<tr><td>${r.mode}</td><td>${r.tol.toPrecision(2)}</td><td>${r.edges}</td>` +
                                     `<td>${r.deviation.toExponential(2)}</td></tr>`).join("");
  }

  // ---- the panel
  function describe() {
    const list = document.getElementById("curve-list");
    list.innerHTML = "";
    state.curves.forEach((c, i) => {
      const why = S.problem(c);
      list.add(new Option(`${c.keyword} ${c.name} (${c.points.length} points)${why ? " !" : ""}`, String(i)));
    });
    list.value = String(state.selected);
    const c = selectedCurve();
    document.getElementById("curve-name").value = c ? c.name : "";
    document.getElementById("curve-steps").value = c ? c.steps : "";
    const info = document.getElementById("curve-info");
    if (c) {
      const type = S.TYPES[S.stem(c.keyword)], why = S.problem(c), at = casteljauAt(c, state.t);
      info.innerHTML = `${type.title}, ${S.dimOf(c.keyword)}D: ${type.rule}. ` +
        (why ? `<span class="problem">${why}</span>` : `${S.segments(c).length} segments, ${S.tessellate(c).points.length} samples.`) +
        (at ? ` de Casteljau on segment ${at.segment} at t = ${at.t.toFixed(3)}.` : "");
    } else info.textContent = "no curve";
    const p = c && state.point >= 0 ? c.points[state.point] : null;
    document.getElementById("point-info").textContent = p ? `point ${state.point}: (${p.slice(0, S.dimOf(c.keyword)).join(", ")})` : "none selected";
    document.getElementById("t-value").textContent = state.t.toFixed(3);
    const out = S.swp(state.curves);
    document.getElementById("swp").value = out.text || "";
    document.getElementById("swp-problem").textContent = out.error ? "cannot export: " + out.error : "";
    document.getElementById("download").disabled = !!out.error;
  }

  function edited(c) {
    c.edited = true;
    redraw();
  }

  // ---- the mouse: screen positions, planes, picking
  function screenOf(p) {
    const rect = renderer.domElement.getBoundingClientRect();
    const s = new THREE.Vector3(p[0], p[1], p[2]).project(camera);
    return {x: rect.left + (s.x + 1) / 2 * rect.width, y: rect.top + (1 - s.y) / 2 * rect.height};
  }

  function rayAt(event) {
    const rect = renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2((event.clientX - rect.left) / rect.width * 2 - 1, 1 - (event.clientY - rect.top) / rect.height * 2);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, camera);
    return ray.ray;
  }

  function snap(v) {
    if (!document.getElementById("snap").checked) return v;
    const step = Number(document.getElementById("snap-step").value);
    return step > 0 && isFinite(step) ? Math.round(v / step) * step : v;
  }

  /// Where the mouse meets the drag plane: z = const (horizontal), or, vertical, the plane through
  /// `through` facing the camera's horizontal direction (only z changes there).
  function planePoint(event, through, vertical) {
    const ray = rayAt(event), o = new THREE.Vector3(through[0], through[1], through[2]);
    let normal;
    if (vertical) {
      const d = new THREE.Vector3();
      camera.getWorldDirection(d);
      d.z = 0;
      if (d.lengthSq() === 0) return null;  // looking straight down: no vertical plane faces us
      normal = d.normalize();
    } else normal = new THREE.Vector3(0, 0, 1);
    const hit = ray.intersectPlane(new THREE.Plane().setFromNormalAndCoplanarPoint(normal, o), new THREE.Vector3());
    if (!hit) return null;
    if (vertical) return [through[0], through[1], snap(hit.z)];
    return [snap(hit.x), snap(hit.y), through[2]];
  }

  function pick(event) {
    let best = null;
    state.curves.forEach((c, i) => c.points.forEach((p, k) => {
      const s = screenOf(p), d = Math.hypot(s.x - event.clientX, s.y - event.clientY);
      if (d <= PICK_PIXELS && (!best || d < best.d || (d === best.d && i === state.selected))) best = {curve: i, point: k, d};
    }));
    return best;
  }

  let press = null;  // {x, y, hit, moved}
  view.addEventListener("mousedown", (e) => {
    if (e.button !== 0) return;
    const hit = pick(e);
    press = {x: e.clientX, y: e.clientY, hit, moved: false};
    if (hit) {
      controls.enabled = false;  // this press drags a point, not the view
      state.selected = hit.curve;
      state.point = hit.point;
      redraw();
    }
  }, true);  // capture: before OrbitControls sees the press

  window.addEventListener("mousemove", (e) => {
    if (!press) return;
    if (Math.hypot(e.clientX - press.x, e.clientY - press.y) >= CLICK_PIXELS) press.moved = true;
    if (!press.hit || !press.moved || e.altKey) return;
    const c = state.curves[press.hit.curve], p = c.points[press.hit.point];
    const vertical = state.mode3d && e.shiftKey && S.dimOf(c.keyword) === 3;
    const q = planePoint(e, p, vertical);
    if (q && (q[0] !== p[0] || q[1] !== p[1] || q[2] !== p[2])) {
      c.points[press.hit.point] = q;
      edited(c);
    }
  });

  window.addEventListener("mouseup", (e) => {
    if (!press) return;
    const was = press;
    press = null;
    controls.enabled = true;
    if (was.moved || e.button !== 0) return;
    if (was.hit && e.altKey) return removePoint(was.hit.curve, was.hit.point);
    if (was.hit || e.target !== renderer.domElement) return;
    addPoint(e);
  });

  /// A click on empty space adds a point after the selected one (or at the end), on the
  /// horizontal plane through that point (z = 0 for a 2D curve or an empty one).
  function addPoint(event) {
    const c = selectedCurve();
    if (!c) return;
    const after = state.point >= 0 ? state.point : c.points.length - 1;
    const z = S.dimOf(c.keyword) === 3 && after >= 0 ? c.points[after][2] : 0;
    const q = planePoint(event, [0, 0, z], false);
    if (!q) return;
    c.points.splice(after + 1, 0, q);
    state.point = after + 1;
    edited(c);
  }

  function removePoint(curve, point) {
    const c = state.curves[curve];
    c.points.splice(point, 1);
    state.selected = curve;
    state.point = Math.min(point, c.points.length - 1);
    edited(c);
  }

  window.addEventListener("keydown", (e) => {
    if ((e.key === "Delete" || e.key === "Backspace") && e.target.tagName !== "INPUT" && state.point >= 0)
      removePoint(state.selected, state.point);
  });

  // ---- panel controls
  const on = (id, ev, f) => document.getElementById(id).addEventListener(ev, f);
  on("curve-list", "change", (e) => {
    state.selected = Number(e.target.value);
    state.point = -1;
    if (state.solo) {
      state.mode3d = S.dimOf(selectedCurve().keyword) === 3;
      makeCamera();
    }
    redraw();
  });
  on("solo", "change", (e) => { state.solo = e.target.checked; makeCamera(); redraw(); });
  on("new-curve", "click", () => {
    const stem = document.getElementById("new-type").value, dim = document.getElementById("new-dim").value;
    let n = state.curves.length + 1;
    while (state.curves.some((c) => c.name === "curve" + n)) ++n;
    state.curves.push({name: "curve" + n, keyword: stem + dim, steps: 16, points: [], core: null, edited: true});
    state.selected = state.curves.length - 1;
    state.point = -1;
    redraw();
  });
  on("delete-curve", "click", () => {
    if (!state.curves.length) return;
    state.curves.splice(state.selected, 1);
    state.selected = Math.max(0, Math.min(state.selected, state.curves.length - 1));
    state.point = -1;
    redraw();
  });
  on("curve-name", "change", (e) => { const c = selectedCurve(); if (c) { c.name = e.target.value.trim(); redraw(); } });
  on("curve-steps", "change", (e) => { const c = selectedCurve(); if (c) { c.steps = Number(e.target.value); edited(c); } });
  on("remove-point", "click", () => { if (state.point >= 0) removePoint(state.selected, state.point); });
  on("t", "input", (e) => { state.t = Number(e.target.value); redraw(); });
  for (const id of ["show-polygon", "show-casteljau", "show-samples", "core-run", "core-frames"]) on(id, "change", redraw);
  on("toggle-3d", "click", () => { state.mode3d = !state.mode3d; makeCamera(); redraw(); });
  on("download", "click", () => {
    const out = S.swp(state.curves);
    if (out.error) return;
    const a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([out.text], {type: "text/plain"}));
    a.download = "curves.swp";
    a.click();
  });

  document.getElementById("title").textContent = data.title || "Curve editor";
  document.getElementById("solo").checked = state.solo;
  if (data.skipped && data.skipped.length)
    document.getElementById("help").insertAdjacentHTML("afterbegin",
      "<p class='problem'>Not editable here, left out: " + data.skipped.map((s) => s.replace(/</g, "&lt;")).join("; ") + "</p>");
  window.addEventListener("resize", resize);
  resize();
  redraw();

  window.crossdivEditor = {state, screenOf, redraw, swp: () => S.swp(state.curves), tessellate: (i) => S.tessellate(state.curves[i]),
                           casteljau: (i, t) => { const at = casteljauAt(state.curves[i], t); return at && S.casteljau(at.control, at.t); },
                           renderer, get camera() { return camera; }};
})();
