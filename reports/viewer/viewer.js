// crossdiv's 3D divergence viewer: the refined mesh of the implementation under test, coloured
// by each vertex's distance to a chosen reference at a chosen level, the worst vertex marked,
// the coarse ancestors of the picked vertex highlighted on the control net. Where the case
// compares texture coordinates: the surface textured with a checkerboard through them (coloured
// by each corner's distance to the reference's value), the UV layout in 2D with its seams, and
// every implementation's value at the picked corner.
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
        uv: l.uv ? { name: l.uv.name, dimension: l.uv.dimension, values: new Float64Array(bytes(l.uv.values)),
                     corners: new Int32Array(bytes(l.uv.corners)) } : null,
      })),
      references: {},
      referenceUvs: {},
      uvWorstCorner: data.uv_worst_corner === undefined ? -1 : data.uv_worst_corner,
    };
    for (const [name, perLevel] of Object.entries(data.references))
      view.references[name] = perLevel.map((o) => (o === null ? null : new Float32Array(bytes(o))));
    for (const [name, values] of Object.entries(data.reference_uvs || {}))
      view.referenceUvs[name] = values === null ? null : new Float64Array(bytes(values));
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

  // The corner (an index into the level's face corners, as the texture coordinates' `corners`
  // are numbered) of every triangle slot: a polygon's fan v0 v1 v2, v0 v2 v3, ... takes its
  // corners 0, j + 1, j + 2. Cached on the level.
  function slotCorners(L) {
    if (L.slotCorners) return L.slotCorners;
    const out = new Int32Array(L.triangles.length);
    if (!L.sizes) for (let i = 0; i < out.length; ++i) out[i] = i;
    else {
      let slot = 0, start = 0;
      for (const n of L.sizes) {
        for (let j = 0; j < n - 2; ++j) { out[slot++] = start; out[slot++] = start + j + 1; out[slot++] = start + j + 2; }
        start += n;
      }
    }
    return (L.slotCorners = out);
  }

  // A corner of vertex v (its first in face order), for showing values where only a vertex
  // was chosen; -1 when the level has no texture coordinates.
  function cornerOfVertex(L, v) {
    if (!L.uv) return -1;
    const T = L.triangles, C = slotCorners(L);
    for (let i = 0; i < T.length; ++i) if (T[i] === v) return C[i];
    return -1;
  }

  // The face a corner belongs to and its place in it.
  function cornerFace(L, corner) {
    if (!L.sizes) return [Math.floor(corner / 3), corner % 3];
    if (!L.faceStarts) {
      L.faceStarts = new Int32Array(L.sizes.length + 1);
      L.sizes.forEach((n, f) => { L.faceStarts[f + 1] = L.faceStarts[f] + n; });
    }
    let lo = 0, hi = L.sizes.length;  // the last face whose start is <= corner
    while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (L.faceStarts[mid] <= corner) lo = mid; else hi = mid; }
    return [lo, corner - L.faceStarts[lo]];
  }

  // The value (u, v) at a corner of a level's channel.
  function uvAt(L, corner) {
    const d = L.uv.dimension, i = L.uv.corners[corner] * d;
    return [L.uv.values[i], d > 1 ? L.uv.values[i + 1] : 0];
  }

  // The box of a channel's values: [umin, vmin, size of its larger side, its diagonal (what
  // crossdiv's face-varying tolerances are relative to)].
  function uvBox(uv) {
    let u0 = Infinity, v0 = Infinity, u1 = -Infinity, v1 = -Infinity;
    const d = uv.dimension;
    for (let i = 0; i < uv.values.length; i += d) {
      u0 = Math.min(u0, uv.values[i]); u1 = Math.max(u1, uv.values[i]);
      if (d > 1) { v0 = Math.min(v0, uv.values[i + 1]); v1 = Math.max(v1, uv.values[i + 1]); }
    }
    if (d === 1) { v0 = 0; v1 = 0; }
    return [u0, v0, Math.max(u1 - u0, v1 - v0) || 1, Math.hypot(u1 - u0, v1 - v0)];
  }

  // How far the reference's value is from ours at every corner of the last level (NaN: its
  // face has no partner), its maximum and where it is reached: the largest component
  // difference, as crossdiv's comparison measures it (harness/corner_values.h).
  function uvDistances(view, reference) {
    const L = view.levels[view.levels.length - 1], theirs = view.referenceUvs[reference];
    const n = L.uv ? L.uv.corners.length : 0, d = L.uv ? L.uv.dimension : 0;
    const dist = new Float64Array(n).fill(NaN);
    let max = 0, worst = -1;
    if (!theirs) return { d: dist, max, worst, mapped: false };
    for (let c = 0; c < n; ++c) {
      let largest = 0;
      for (let k = 0; k < d; ++k) largest = Math.max(largest, Math.abs(theirs[c * d + k] - L.uv.values[L.uv.corners[c] * d + k]));
      dist[c] = largest;
      if (Number.isFinite(dist[c]) && (worst < 0 || dist[c] > max)) { max = dist[c]; worst = c; }
    }
    return { d: dist, max, worst, mapped: true };
  }

  // A checkerboard of 8 x 8 squares with a finer grid, drawn once: what a texture artist
  // checks UVs with (stretching, flips and seams show as bent, uneven or broken squares).
  let checker = null;
  function checkerTexture() {
    if (checker) return checker;
    const canvas = document.createElement("canvas");
    canvas.width = canvas.height = 512;
    const g = canvas.getContext("2d");
    for (let i = 0; i < 8; ++i)
      for (let j = 0; j < 8; ++j) {
        g.fillStyle = (i + j) % 2 ? "#3b4a5a" : "#f2f2f2";
        g.fillRect(64 * i, 64 * j, 64, 64);
      }
    g.fillStyle = "#c62828";  // the origin's square, to show which way the layout turns
    g.fillRect(0, 512 - 64, 32, 32);
    checker = new THREE.CanvasTexture(canvas);
    checker.wrapS = checker.wrapT = THREE.RepeatWrapping;
    return checker;
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
      texture: root.querySelector(".cv-texture"), uv: root.querySelector(".cv-uv"),
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
    this.state = { entry: null, view: null, reference: null, level: 0, vertex: -1, corner: -1 };

    entries.forEach((e, i) => {
      const o = document.createElement("option");
      o.value = i;
      o.textContent = e.label;
      this.ui.cases.appendChild(o);
    });
    this.ui.cases.addEventListener("change", () => this.show(Number(this.ui.cases.value)));
    this.ui.reference.addEventListener("change", () => { this.state.reference = this.ui.reference.value; this.rebuild(false); });
    this.ui.level.addEventListener("change", () => {
      this.state.level = Number(this.ui.level.value);
      this.state.vertex = this.state.corner = -1;
      this.rebuild(true);
    });
    for (const box of [this.ui.net, this.ui.wire, this.ui.flat, this.ui.texture])
      if (box) box.addEventListener("change", () => this.rebuild(false));

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
      this.state = { entry, view, reference: entry.reference, level: view.levels.length - 1, vertex: entry.worst_vertex, corner: -1 };
      // A case whose texture coordinates diverge opens at their worst corner when its
      // positions agree (no worst vertex), or when that corner is the worst vertex's.
      const last = view.levels[view.levels.length - 1];
      if (view.uvWorstCorner >= 0 && last.uv) {
        const at = last.triangles.length ? cornerVertex(last, view.uvWorstCorner) : -1;
        if (this.state.vertex < 0 || this.state.vertex === at) { this.state.vertex = at; this.state.corner = view.uvWorstCorner; }
      }
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
    const textured = !!(this.ui.texture && this.ui.texture.checked && L.uv);
    const uvDist = textured && level === view.levels.length - 1 ? uvDistances(view, reference) : null;
    this.uvDist = uvDist;
    const geometry = textured ? texturedGeometry(view, L, uvDist) : new THREE.BufferGeometry();
    if (!textured) {
      const position = new Float32Array(L.positions);
      const colours = new Float32Array(position.length);
      for (let v = 0; v < dist.d.length; ++v) colour(dist.max > 0 ? dist.d[v] / dist.max : dist.mapped ? 0 : NaN).forEach((c, k) => { colours[3 * v + k] = c; });
      geometry.setAttribute("position", new THREE.BufferAttribute(position, 3));
      geometry.setAttribute("color", new THREE.BufferAttribute(colours, 3));
      geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(L.triangles), 1));
      geometry.computeVertexNormals();
    }
    geometry.computeBoundingSphere();
    this.mesh = new THREE.Mesh(geometry, new THREE.MeshPhongMaterial({
      vertexColors: THREE.VertexColors, side: THREE.DoubleSide, flatShading: this.ui.flat.checked,
      map: textured ? checkerTexture() : null,
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
      const c = sphere.center, w = this.state.vertex, N = vertexNormals(L);
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
      (textured ? uvLine(view, reference, level, uvDist)
       : dist.mapped ? "largest distance to " + escapeHtml(reference) + " " + fmt(dist.max) + " at v" + dist.worst + " (colour scale 0 .. " + fmt(dist.max) + ")"
                   : escapeHtml(reference) + " has no vertex map at this level (grey)");
    this.drawUv();
    this.draw();
  };

  // What the colours of the textured surface say.
  function uvLine(view, reference, level, uvDist) {
    if (!uvDist) return "texture coordinates (checkerboard); the references' values are kept at the last level only";
    if (!uvDist.mapped) return "texture coordinates (checkerboard); " + escapeHtml(reference) + " gave no texture coordinates (grey)";
    const L = view.levels[level], box = uvBox(L.uv);
    return "texture coordinates (checkerboard), coloured by the difference from " + escapeHtml(reference) + "'s value at each corner: largest " +
      fmt(uvDist.max) + " (" + fmt(uvDist.max / (box[3] || 1)) + " of the UV box) at corner " + uvDist.worst + " of face " + cornerFace(L, uvDist.worst)[0];
  }

  // Smooth normals per vertex of a level (cached): the textured surface is drawn with its
  // corners apart, and takes its normals from here so that it shades as the untextured one.
  function vertexNormals(L) {
    if (L.normals) return L.normals;
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(new Float32Array(L.positions), 3));
    g.setIndex(new THREE.BufferAttribute(new Uint32Array(L.triangles), 1));
    g.computeVertexNormals();
    return (L.normals = g.attributes.normal.array);
  }

  // The level drawn corner by corner (three slots per triangle, in the triangles' order, so that
  // a ray's faceIndex is the triangle's), each slot with its corner's texture coordinates
  // normalised to the input's UV box and the colour of its corner's distance to the reference.
  function texturedGeometry(view, L, uvDist) {
    const T = L.triangles, C = slotCorners(L), N = vertexNormals(L), P = L.positions;
    const box = uvBox(view.levels[0].uv || L.uv);
    const position = new Float32Array(3 * T.length), normal = new Float32Array(3 * T.length);
    const uv = new Float32Array(2 * T.length), colours = new Float32Array(3 * T.length);
    for (let i = 0; i < T.length; ++i) {
      const v = T[i], [u, w] = uvAt(L, C[i]);
      for (let k = 0; k < 3; ++k) { position[3 * i + k] = P[3 * v + k]; normal[3 * i + k] = N[3 * v + k]; }
      uv[2 * i] = (u - box[0]) / box[2];  // the box is the texture's square: 8 x 8 checks across it
      uv[2 * i + 1] = (w - box[1]) / box[2];
      const c = !uvDist ? [1, 1, 1] : colour(uvDist.max > 0 ? uvDist.d[C[i]] / uvDist.max : uvDist.mapped ? 0 : NaN);
      const tint = c.map((x) => 0.35 + 0.65 * x);  // keep the squares visible under dark red
      for (let k = 0; k < 3; ++k) colours[3 * i + k] = tint[k];
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(position, 3));
    g.setAttribute("normal", new THREE.BufferAttribute(normal, 3));
    g.setAttribute("uv", new THREE.BufferAttribute(uv, 2));
    g.setAttribute("color", new THREE.BufferAttribute(colours, 3));
    return g;
  }

  // The class of the value at a corner, as crossdiv names it (harness/corner_values.h): a
  // junction (three or more values at its vertex), a corner (its value on one face), a seam
  // (two values), else boundary or interior.
  function uvClass(L, corner) {
    const v = cornerVertex(L, corner), value = L.uv.corners[corner], T = L.triangles, C = slotCorners(L);
    const values = new Set(), faces = new Set();
    for (let i = 0; i < T.length; ++i) {
      if (T[i] !== v) continue;
      values.add(L.uv.corners[C[i]]);
      if (L.uv.corners[C[i]] === value) faces.add(cornerFace(L, C[i])[0]);
    }
    if (values.size >= 3) return "junction";
    if (faces.size === 1) return "UV corner";
    if (values.size === 2) return "seam";
    return L.boundary[v] ? "boundary" : "interior";
  }

  // The vertex at a corner of a level.
  function cornerVertex(L, corner) {
    const C = slotCorners(L);
    for (let i = 0; i < C.length; ++i) if (C[i] === corner) return L.triangles[i];
    return -1;
  }

  // The UV layout of the shown level in 2D: every face's edges in UV, the seams (an edge whose
  // two faces give its ends different values) in red, the UV boundary darker, the picked corner
  // green and each reference's value there as a ring.
  Viewer.prototype.drawUv = function () {
    const canvas = this.ui.uv;
    if (!canvas) return;
    const { view, level, corner, reference } = this.state;
    const L = view.levels[level];
    const box = canvas.parentNode;
    box.style.display = L.uv ? "" : "none";
    if (!L.uv) return;
    const size = 300, pad = 12, ratio = window.devicePixelRatio || 1;
    canvas.width = canvas.height = size * ratio;
    const g = canvas.getContext("2d");
    g.setTransform(ratio, 0, 0, ratio, 0, 0);
    g.fillStyle = "#ffffff";
    g.fillRect(0, 0, size, size);
    const [u0, v0, span] = uvBox(view.levels[0].uv || L.uv);
    const at = (p) => [pad + (p[0] - u0) / span * (size - 2 * pad), size - pad - (p[1] - v0) / span * (size - 2 * pad)];
    // Each edge once, keyed by its vertices: the values at its ends on each side.
    const n = L.positions.length / 3, edges = new Map();
    const cycles = L.cycles || (L.cycles = faceCycles(L));
    let start = 0;
    for (const cycle of cycles) {
      for (let k = 0; k < cycle.length; ++k) {
        const a = cycle[k], b = cycle[(k + 1) % cycle.length];
        const ca = start + k, cb = start + (k + 1) % cycle.length;
        const key = a < b ? a * n + b : b * n + a;
        const ends = a < b ? [L.uv.corners[ca], L.uv.corners[cb]] : [L.uv.corners[cb], L.uv.corners[ca]];
        const e = edges.get(key);
        if (!e) edges.set(key, { sides: [ends], from: [ca, cb] });
        else e.sides.push(ends);
      }
      start += cycle.length;
    }
    const stroke = (p, q, colour, width) => {
      g.strokeStyle = colour; g.lineWidth = width;
      g.beginPath(); g.moveTo(...at(p)); g.lineTo(...at(q)); g.stroke();
    };
    const d = L.uv.dimension, value = (i) => [L.uv.values[i * d], d > 1 ? L.uv.values[i * d + 1] : 0];
    let seams = 0;
    const later = [];
    for (const e of edges.values()) {
      const [a, b] = e.sides[0];
      const seam = e.sides.some(([x, y]) => x !== a || y !== b);
      if (seam) { seams++; for (const [x, y] of e.sides) later.push([value(x), value(y), "#d32f2f", 2]); }
      else stroke(value(a), value(b), e.sides.length === 1 ? "#455a64" : "#b0bec5", e.sides.length === 1 ? 1.5 : 0.7);
    }
    for (const args of later) stroke(...args);
    this.uvSeams = seams;
    if (corner >= 0 && corner < L.uv.corners.length) {
      const dot = (p, colour, r, fill) => {
        g.beginPath(); g.arc(...at(p), r, 0, 2 * Math.PI);
        if (fill) { g.fillStyle = colour; g.fill(); } else { g.strokeStyle = colour; g.lineWidth = 2; g.stroke(); }
      };
      dot(uvAt(L, corner), "#00c853", 4, true);
      const theirs = level === view.levels.length - 1 && view.referenceUvs[reference];
      if (theirs && Number.isFinite(theirs[corner * d])) dot([theirs[corner * d], d > 1 ? theirs[corner * d + 1] : 0], "#6a1b9a", 7, false);
    }
    box.querySelector(".cv-uv-text").textContent = "UV layout at level " + level + ": " + edges.size + " edges, " + seams +
      " on a seam (red); green: the picked corner, ringed: " + reference + "'s value there";
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
    const uvRun = entry.runs.find((r) => r.reference === reference && r.check && r.check.startsWith("texture"));
    // The texture coordinates at the picked corner (a vertex picked without one: its first).
    let corner = this.state.corner;
    if (L.uv && (corner < 0 || cornerVertex(L, corner) !== vertex)) corner = this.state.corner = cornerOfVertex(L, vertex);
    const uvRows = [];
    if (L.uv && corner >= 0) {
      const ours = uvAt(L, corner), d = L.uv.dimension;
      uvRows.push([view.subject, vec(ours), "-"]);
      for (const [name, theirs] of Object.entries(view.referenceUvs)) {
        if (level !== view.levels.length - 1) { uvRows.push([name, "kept at the last level only", "-"]); continue; }
        if (!theirs) { uvRows.push([name, "gave no texture coordinates", "-"]); continue; }
        const q = [theirs[corner * d], d > 1 ? theirs[corner * d + 1] : 0];
        uvRows.push([name, vec(q), fmt(Math.max(Math.abs(q[0] - ours[0]), Math.abs(q[1] - ours[1])))]);
      }
    }
    const [face, place] = corner >= 0 ? cornerFace(L, corner) : [-1, -1];
    this.pickedInfo = { level, vertex, cls: vertexClass(view, level, vertex), valence: L.valence[vertex], ancestors: roots, rows,
                        corner, face, uvRows };
    this.picked.innerHTML = "<b>v" + vertex + "</b> at level " + level + (vertex === entry.worst_vertex && level === view.levels.length - 1 ? " (the case's worst vertex)" : "") +
      "<br>" + escapeHtml(this.pickedInfo.cls) +
      (roots.length ? "<br>descends from input vertices " + roots.map((a) => "v" + a).join(", ") : "") +
      (run ? "<br>" + escapeHtml(reference) + ": " + escapeHtml(run.outcome) + (run.explanation ? " — " + escapeHtml(run.explanation) : "") : "") +
      "<table><tr><th>implementation</th><th>position</th><th>distance</th></tr>" +
      rows.map((r) => "<tr><td>" + r.map(escapeHtml).join("</td><td>") + "</td></tr>").join("") + "</table>" +
      (uvRows.length ? "<p>corner " + place + " of face " + face + " (" + uvClass(L, corner) + ")" +
        (uvRun ? ": " + escapeHtml(uvRun.outcome) + (uvRun.explanation ? " — " + escapeHtml(uvRun.explanation) : "") : "") + "</p>" +
        "<table class='cv-uv-table'><tr><th>implementation</th><th>texture coordinates</th><th>difference</th></tr>" +
        uvRows.map((r) => "<tr><td>" + r.map(escapeHtml).join("</td><td>") + "</td></tr>").join("") + "</table>" : "");
  };

  Viewer.prototype.pickAt = function (clientX, clientY) {
    const rect = this.canvas.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, this.camera);
    const hit = ray.intersectObject(this.mesh)[0];
    if (!hit) return false;
    // The hit triangle's corner nearest the hit point: its vertex, and its face corner (the
    // vertex's value on the side that was clicked, where a seam gives it two).
    const L = this.state.view.levels[this.state.level], P = L.positions;
    let best = -1, bestD = Infinity;
    for (let k = 0; k < 3; ++k) {
      const v = L.triangles[3 * hit.faceIndex + k];
      const d = hit.point.distanceToSquared(new THREE.Vector3(P[3 * v], P[3 * v + 1], P[3 * v + 2]));
      if (d < bestD) { bestD = d; best = 3 * hit.faceIndex + k; }
    }
    this.state.vertex = L.triangles[best];
    this.state.corner = L.uv ? slotCorners(L)[best] : -1;
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
