// crossdiv's 3D divergence viewer: the refined mesh of the implementation under test, coloured
// by each vertex's distance to a chosen reference at a chosen level, the worst vertex marked,
// the coarse ancestors of the picked vertex highlighted on the control net.
//
// Runs from disk, offline: three.js and its OrbitControls are Debian's (libjs-three), copied
// beside this file by the report. Each case's data is a script views/jobN.js, written by
// `crossdiv suite` (reports/results-schema.md), that calls crossdivView(data); it is loaded
// when the case is first shown. The page lists the cases in window.CROSSDIV_VIEWS.
(function () {
  "use strict";

  const loaded = {};   // job -> decoded view
  const waiting = {};  // job -> resolve of the promise that loads it

  function bytes(b64) {
    const s = atob(b64);
    const out = new Uint8Array(s.length);
    for (let i = 0; i < s.length; ++i) out[i] = s.charCodeAt(i);
    return out.buffer;
  }

  // The side file's entry point: decode the arrays once.
  window.crossdivView = function (data) {
    const view = {
      job: data.job, subject: data.subject,
      levels: data.levels.map((l) => ({
        positions: new Float64Array(bytes(l.positions)),
        triangles: new Int32Array(bytes(l.triangles)),
        sizes: l.sizes ? new Int32Array(bytes(l.sizes)) : null,
        origins: l.origins ? new Int32Array(bytes(l.origins)) : null,
      })),
      references: {},
    };
    for (const [name, perLevel] of Object.entries(data.references))
      view.references[name] = perLevel.map((o) => (o === null ? null : new Float32Array(bytes(o))));
    for (const level of view.levels) describeVertices(level);
    if (data.minimal) {
      const m = data.minimal;
      view.minimal = Object.assign({}, m, { positions: new Float64Array(bytes(m.positions)), triangles: new Int32Array(bytes(m.triangles)),
                                            sizes: m.sizes ? new Int32Array(bytes(m.sizes)) : null });
      describeVertices(view.minimal);
    }
    loaded[data.job] = view;
    if (waiting[data.job]) waiting[data.job](view);
  };

  function load(entry) {
    if (loaded[entry.job]) return Promise.resolve(loaded[entry.job]);
    return new Promise((resolve, reject) => {
      waiting[entry.job] = resolve;
      const script = document.createElement("script");
      script.src = entry.view;
      script.onerror = () => reject(new Error("cannot load " + entry.view));
      document.head.appendChild(script);
    });
  }

  // The faces' corner cycles: the triangles, or with `sizes` the polygons they fan (a face of
  // n corners is n - 2 triangles from its first corner: v0 v1 v2, v0 v2 v3, ...).
  function faceCycles(level) {
    const t = level.triangles, cycles = [];
    if (!level.sizes) {
      for (let i = 0; i < t.length; i += 3) cycles.push([t[i], t[i + 1], t[i + 2]]);
      return cycles;
    }
    let i = 0;
    for (const n of level.sizes) {
      const cycle = [t[i], t[i + 1]];
      for (let k = 0; k < n - 2; ++k, i += 3) cycle.push(t[i + 2]);
      cycles.push(cycle);
    }
    return cycles;
  }

  // Valence (distinct neighbours) and boundary (an edge with one face) of every vertex, and the
  // edges for the wireframe (the polygons' edges, not their fans'); linear in the mesh size
  // (each edge keyed once in a Map).
  function describeVertices(level) {
    const n = level.positions.length / 3;
    const uses = new Map();
    for (const cycle of faceCycles(level))
      for (let k = 0; k < cycle.length; ++k) {
        const a = cycle[k], b = cycle[(k + 1) % cycle.length];
        const key = a < b ? a * n + b : b * n + a;
        uses.set(key, (uses.get(key) || 0) + 1);
      }
    level.valence = new Int32Array(n);
    level.boundary = new Uint8Array(n);
    level.edges = new Int32Array(2 * uses.size);
    let e = 0;
    for (const [key, count] of uses) {
      const a = Math.floor(key / n), b = key % n;
      level.valence[a]++; level.valence[b]++;
      if (count === 1) level.boundary[a] = level.boundary[b] = 1;
      level.edges[e++] = a; level.edges[e++] = b;
    }
  }

  // Distance of every vertex from the reference's position (NaN: unmatched), its finite maximum
  // and the vertex where it is reached.
  function distances(view, reference, level) {
    const offsets = view.references[reference] && view.references[reference][level];
    const n = view.levels[level].positions.length / 3;
    const d = new Float64Array(n).fill(NaN);
    let max = 0, worst = -1;
    if (!offsets) return { d, max, worst, mapped: false };
    for (let v = 0; v < n; ++v) {
      const x = offsets[3 * v], y = offsets[3 * v + 1], z = offsets[3 * v + 2];
      d[v] = Math.sqrt(x * x + y * y + z * z);
      if (Number.isFinite(d[v]) && (worst < 0 || d[v] > max)) { max = d[v]; worst = v; }
    }
    return { d, max, worst, mapped: true };
  }

  // Light where the two agree, through orange to dark red where they part most; grey where
  // the reference has no matched vertex.
  const STOPS = [[222, 230, 238], [253, 219, 160], [252, 141, 89], [215, 48, 31], [127, 0, 0]];
  function colour(t) {
    if (!(t >= 0)) return [0.45, 0.45, 0.45];
    const x = Math.min(t, 1) * (STOPS.length - 1), i = Math.min(Math.floor(x), STOPS.length - 2), f = x - i;
    return STOPS[i].map((c, k) => (c + f * (STOPS[i + 1][k] - c)) / 255);
  }

  function fmt(x) { return Number.isFinite(x) ? x.toPrecision(6) : "-"; }
  function vec(p) { return "(" + Array.from(p, (c) => Number.isFinite(c) ? c.toPrecision(12) : "NaN").join(", ") + ")"; }

  // The corners of face f of a level (faceCycles, read once per level).
  function faceCorners(L, f) {
    if (!L.cycles) L.cycles = faceCycles(L);
    return L.cycles[f];
  }

  // The level-0 vertices a vertex of `level` descends from: through a vertex point one
  // vertex, through an edge point the edge's ends, through a face point the face's corners,
  // level by level; none where a level has no provenance (Doo-Sabin, sqrt3).
  function ancestors(view, level, vertex) {
    let set = new Set([vertex]);
    for (let l = level; l >= 1; --l) {
      const o = view.levels[l].origins, next = new Set();
      if (!o) return [];
      for (const v of set) {
        const a = o[2 * v], b = o[2 * v + 1];
        if (b === -2) for (const c of faceCorners(view.levels[l - 1], a)) next.add(c);
        else {
          next.add(a);
          if (b >= 0) next.add(b);
        }
      }
      set = next;
    }
    return Array.from(set).sort((a, b) => a - b);
  }

  function vertexClass(view, level, v) {
    const L = view.levels[level];
    const where = (L.boundary[v] ? "boundary" : "interior") + ", valence " + L.valence[v];
    if (level === 0) return "input vertex, " + where;
    if (!L.origins) return "vertex of level " + level + ", " + where;
    const a = L.origins[2 * v], b = L.origins[2 * v + 1];
    const born = b === -2 ? "face point of face " + a + " (v" + faceCorners(view.levels[level - 1], a).join(", v") + ")"
               : b < 0 ? "vertex point of v" + a : "edge point of edge (v" + a + ", v" + b + ")";
    return born + " of level " + (level - 1) + ", " + where;
  }

  function Viewer(root, entries) {
    this.root = root;
    this.entries = entries;
    this.canvas = root.querySelector("canvas");
    this.info = root.querySelector(".cv-info");
    this.picked = root.querySelector(".cv-picked");
    this.ui = {
      cases: root.querySelector(".cv-case"), reference: root.querySelector(".cv-reference"),
      level: root.querySelector(".cv-level"), net: root.querySelector(".cv-net"),
      wire: root.querySelector(".cv-wire"), flat: root.querySelector(".cv-flat"),
    };
    this.renderer = new THREE.WebGLRenderer({ canvas: this.canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(0xf4f4f4);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(35, this.canvas.clientWidth / this.canvas.clientHeight, 1e-3, 1e3);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 0.9));
    const sun = new THREE.DirectionalLight(0xffffff, 0.5);
    this.camera.add(sun);
    this.scene.add(this.camera);
    this.controls = new THREE.OrbitControls(this.camera, this.canvas);
    this.controls.addEventListener("change", () => this.draw());
    this.group = new THREE.Group();
    this.scene.add(this.group);
    this.state = { entry: null, view: null, reference: null, level: 0, vertex: -1 };

    entries.forEach((e, i) => {
      const o = document.createElement("option");
      o.value = i;
      o.textContent = e.label;
      this.ui.cases.appendChild(o);
    });
    this.ui.cases.addEventListener("change", () => this.show(Number(this.ui.cases.value)));
    this.ui.reference.addEventListener("change", () => { this.state.reference = this.ui.reference.value; this.rebuild(false); });
    this.ui.level.addEventListener("change", () => { this.state.level = Number(this.ui.level.value); this.state.vertex = -1; this.rebuild(true); });
    for (const box of [this.ui.net, this.ui.wire, this.ui.flat]) box.addEventListener("change", () => this.rebuild(false));

    // A click that did not drag picks the vertex nearest the hit point.
    let down = null;
    this.canvas.addEventListener("pointerdown", (ev) => { down = [ev.clientX, ev.clientY]; });
    this.canvas.addEventListener("pointerup", (ev) => {
      if (down && Math.hypot(ev.clientX - down[0], ev.clientY - down[1]) < 4) this.pickAt(ev.clientX, ev.clientY);
      down = null;
    });
  }

  Viewer.prototype.show = function (index) {
    const entry = this.entries[index];
    this.ui.cases.value = index;
    this.info.textContent = "loading " + entry.view + " ...";
    return load(entry).then((view) => {
      this.state = { entry, view, reference: entry.reference, level: view.levels.length - 1, vertex: entry.worst_vertex };
      this.ui.reference.innerHTML = "";
      for (const name of Object.keys(view.references)) {
        const o = document.createElement("option");
        o.value = o.textContent = name;
        this.ui.reference.appendChild(o);
      }
      if (!view.references[this.state.reference]) this.state.reference = Object.keys(view.references)[0];
      this.ui.reference.value = this.state.reference;
      this.ui.level.innerHTML = "";
      view.levels.forEach((_, l) => {
        const o = document.createElement("option");
        o.value = l;
        o.textContent = "level " + l;
        this.ui.level.appendChild(o);
      });
      this.ui.level.value = this.state.level;
      this.showMinimal(view.minimal);
      this.rebuild(true);
    }, (err) => { this.info.textContent = err.message; });
  };

  // Rebuilds the scene for the state; `aim` also points the camera at the worst vertex.
  Viewer.prototype.rebuild = function (aim) {
    const { view, reference, level, entry } = this.state;
    const L = view.levels[level];
    const dist = distances(view, reference, level);
    if (this.state.vertex < 0 || this.state.vertex >= L.valence.length) this.state.vertex = dist.worst;
    this.dist = dist;
    for (const child of this.group.children.slice()) {
      this.group.remove(child);
      if (child.geometry) child.geometry.dispose();
    }
    const position = new Float32Array(L.positions);
    const colours = new Float32Array(position.length);
    for (let v = 0; v < dist.d.length; ++v) colour(dist.max > 0 ? dist.d[v] / dist.max : dist.mapped ? 0 : NaN).forEach((c, k) => { colours[3 * v + k] = c; });
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(position, 3));
    geometry.setAttribute("color", new THREE.BufferAttribute(colours, 3));
    geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(L.triangles), 1));
    geometry.computeVertexNormals();
    geometry.computeBoundingSphere();
    this.mesh = new THREE.Mesh(geometry, new THREE.MeshPhongMaterial({
      vertexColors: THREE.VertexColors, side: THREE.DoubleSide, flatShading: this.ui.flat.checked,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
    this.group.add(this.mesh);
    // Framed round the control net and the surface together (the net encloses a Loop surface).
    const box = new THREE.Box3().setFromArray(L.positions).union(new THREE.Box3().setFromArray(view.levels[0].positions));
    const sphere = new THREE.Sphere(box.getCenter(new THREE.Vector3()), 0);
    for (const P of [L.positions, view.levels[0].positions])
      for (let i = 0; i < P.length; i += 3)
        sphere.radius = Math.max(sphere.radius, Math.hypot(P[i] - sphere.center.x, P[i + 1] - sphere.center.y, P[i + 2] - sphere.center.z));
    this.radius = sphere.radius || 1;
    if (this.ui.wire.checked) this.group.add(lines(L.positions, L.edges, 0x222222, 0.35));
    if (this.ui.net.checked && level > 0) this.group.add(lines(view.levels[0].positions, view.levels[0].edges, 0x1565c0, 0.9));
    this.markVertex();
    if (aim) {
      // From outside the marked vertex: along its normal, leaning away from the centre.
      const c = sphere.center, w = this.state.vertex, N = geometry.attributes.normal.array;
      const out = new THREE.Vector3(L.positions[3 * w] - c.x, L.positions[3 * w + 1] - c.y, L.positions[3 * w + 2] - c.z);
      const dir = new THREE.Vector3(N[3 * w], N[3 * w + 1], N[3 * w + 2]);
      if (out.dot(dir) < 0) dir.negate();
      dir.addScaledVector(out, 0.5 / this.radius);
      if (!(dir.length() > 1e-9)) dir.set(0.3, 0.4, 1);
      dir.normalize();
      // Turned a little off the vertex's own direction, so that the surface round it shows
      // its shape rather than facing the camera flat.
      const side = new THREE.Vector3(0, 1, 0).cross(dir);
      if (side.length() < 1e-6) side.set(1, 0, 0);
      dir.addScaledVector(side.normalize(), 0.45).addScaledVector(new THREE.Vector3(0, 1, 0), 0.3).normalize();
      this.controls.target.copy(c);
      this.camera.near = this.radius * 1e-3;
      this.camera.far = this.radius * 100;
      this.camera.position.copy(c).addScaledVector(dir, this.radius / Math.sin(this.camera.fov / 2 * Math.PI / 180));
      this.camera.updateProjectionMatrix();
      this.controls.update();
    }
    this.info.innerHTML = "<b>" + escapeHtml(entry.id) + "</b><br>" + escapeHtml(entry.runs.map((r) => r.reference + ": " + r.outcome).join("; ")) +
      "<br>level " + level + ": " + L.valence.length + " vertices, " +
      (L.sizes ? L.sizes.length + " faces; " : L.triangles.length / 3 + " triangles; ") +
      (dist.mapped ? "largest distance to " + escapeHtml(reference) + " " + fmt(dist.max) + " at v" + dist.worst + " (colour scale 0 .. " + fmt(dist.max) + ")"
                   : escapeHtml(reference) + " has no vertex map at this level (grey)");
    this.draw();
  };

  function lines(positions, edges, colour, opacity) {
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(new Float32Array(positions), 3));
    g.setIndex(new THREE.BufferAttribute(new Uint32Array(edges), 1));
    return new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: colour, transparent: opacity < 1, opacity }));
  }

  function escapeHtml(s) {
    return String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" }[c]));
  }

  // The selected vertex (the worst one until a pick): a marker, its ancestors on the control
  // net, and every implementation's value there.
  Viewer.prototype.markVertex = function () {
    const { view, level, vertex, reference, entry } = this.state;
    const L = view.levels[level], P = L.positions;
    const size = this.radius * 0.025;
    const marker = new THREE.Mesh(new THREE.SphereBufferGeometry(size, 16, 12), new THREE.MeshBasicMaterial({ color: 0x00c853 }));
    marker.position.set(P[3 * vertex], P[3 * vertex + 1], P[3 * vertex + 2]);
    this.group.add(marker);
    const roots = ancestors(view, level, vertex);
    const P0 = view.levels[0].positions;
    for (const a of roots) {
      const m = new THREE.Mesh(new THREE.SphereBufferGeometry(size * 0.8, 12, 8), new THREE.MeshBasicMaterial({ color: 0x1565c0 }));
      m.position.set(P0[3 * a], P0[3 * a + 1], P0[3 * a + 2]);
      this.group.add(m);
    }
    const rows = [[view.subject, vec(P.subarray(3 * vertex, 3 * vertex + 3)), "-"]];
    for (const [name, perLevel] of Object.entries(view.references)) {
      const o = perLevel[level];
      if (!o) { rows.push([name, "no vertex map at this level", "-"]); continue; }
      const q = [0, 1, 2].map((k) => P[3 * vertex + k] + o[3 * vertex + k]);
      rows.push([name, vec(q), fmt(Math.hypot(o[3 * vertex], o[3 * vertex + 1], o[3 * vertex + 2]))]);
    }
    const run = entry.runs.find((r) => r.reference === reference);
    this.pickedInfo = { level, vertex, cls: vertexClass(view, level, vertex), valence: L.valence[vertex], ancestors: roots, rows };
    this.picked.innerHTML = "<b>v" + vertex + "</b> at level " + level + (vertex === entry.worst_vertex && level === view.levels.length - 1 ? " (the case's worst vertex)" : "") +
      "<br>" + escapeHtml(this.pickedInfo.cls) +
      (roots.length ? "<br>descends from input vertices " + roots.map((a) => "v" + a).join(", ") : "") +
      (run ? "<br>" + escapeHtml(reference) + ": " + escapeHtml(run.outcome) + (run.explanation ? " — " + escapeHtml(run.explanation) : "") : "") +
      "<table><tr><th>implementation</th><th>position</th><th>distance</th></tr>" +
      rows.map((r) => "<tr><td>" + r.map(escapeHtml).join("</td><td>") + "</td></tr>").join("") + "</table>";
  };

  Viewer.prototype.pickAt = function (clientX, clientY) {
    const rect = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, this.camera);
    const hit = ray.intersectObject(this.mesh)[0];
    if (!hit) return false;
    const P = this.state.view.levels[this.state.level].positions;
    let best = -1, bestD = Infinity;
    for (const v of [hit.face.a, hit.face.b, hit.face.c]) {
      const d = hit.point.distanceToSquared(new THREE.Vector3(P[3 * v], P[3 * v + 1], P[3 * v + 2]));
      if (d < bestD) { bestD = d; best = v; }
    }
    this.state.vertex = best;
    this.rebuild(false);
    return true;
  };

  // The case shrunk (as `crossdiv diff` shrinks): the minimal input that still shows the
  // divergence, beside the case, in its own small view with its own orbit.
  Viewer.prototype.showMinimal = function (m) {
    const box = this.root.querySelector(".cv-minimal");
    if (!box) return;
    box.style.display = m ? "" : "none";
    if (!m) return;
    if (!this.minimal) {
      // One canvas and one WebGL context for every case (a browser allows few contexts).
      box.innerHTML = "<p class='cv-minimal-text'></p><canvas style='width: 320px; height: 220px'></canvas>";
      const canvas = box.querySelector("canvas");
      const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
      renderer.setClearColor(0xffffff);
      const scene = new THREE.Scene(), camera = new THREE.PerspectiveCamera(35, 320 / 220, 1e-3, 1e3);
      camera.up.set(0, 0, 1);
      scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 0.9));
      const group = new THREE.Group();
      scene.add(group);
      const controls = new THREE.OrbitControls(camera, canvas);
      const draw = () => { renderer.setSize(320, 220, false); renderer.render(scene, camera); };
      controls.addEventListener("change", draw);
      this.minimal = { canvas, group, camera, controls, draw };
    }
    box.querySelector(".cv-minimal-text").innerHTML = "<b>Minimal input</b>: " + m.faces + " face(s) still show that " +
      escapeHtml(m.symptom) + " (" + m.tests + " comparisons while shrinking). In the report's folder: <code>" +
      escapeHtml(m.reproduce) + "</code>";
    const { group, camera, controls, draw } = this.minimal;
    for (const child of group.children.slice()) {
      group.remove(child);
      if (child.geometry) child.geometry.dispose();
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(new Float32Array(m.positions), 3));
    g.setIndex(new THREE.BufferAttribute(new Uint32Array(m.triangles), 1));
    g.computeVertexNormals();
    g.computeBoundingSphere();
    group.add(new THREE.Mesh(g, new THREE.MeshPhongMaterial({ color: 0xf0a070, side: THREE.DoubleSide, flatShading: true,
                                                             polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 })));
    group.add(lines(m.positions, m.edges, 0x1565c0, 1));
    const c = g.boundingSphere.center, r = g.boundingSphere.radius || 1;
    camera.position.copy(c).add(new THREE.Vector3(0.5, -0.8, 1).normalize().multiplyScalar(2.6 * r));
    controls.target.copy(c);
    controls.update();
    draw();
  };

  // Where vertex v of the shown level is on the page (CSS pixels), for a scripted click.
  Viewer.prototype.screenOf = function (v) {
    const P = this.state.view.levels[this.state.level].positions;
    const p = new THREE.Vector3(P[3 * v], P[3 * v + 1], P[3 * v + 2]).project(this.camera);
    const rect = this.canvas.getBoundingClientRect();
    return { x: rect.left + (p.x + 1) / 2 * rect.width, y: rect.top + (1 - p.y) / 2 * rect.height };
  };

  Viewer.prototype.draw = function () {
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.renderer.render(this.scene, this.camera);
  };

  window.addEventListener("load", () => {
    const root = document.getElementById("crossdiv-viewer");
    if (!root || !window.CROSSDIV_VIEWS || !window.CROSSDIV_VIEWS.length) return;
    const viewer = new Viewer(root, window.CROSSDIV_VIEWS);
    window.crossdivViewer = viewer;
    // A link "view" next to a catalogue row opens that case here.
    document.querySelectorAll("a[data-view]").forEach((a) => a.addEventListener("click", () => viewer.show(Number(a.dataset.view))));
    viewer.show(0).then(() => { viewer.ready = true; });
  });
})();
