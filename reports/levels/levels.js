// The seed's subdivision views, side by side: each level of a mesh refined by core under one
// scheme, with the control net (level 0's edges) over every level, the level's own wireframe,
// and flat or smooth shading; one camera turns them all. Data: window.CROSSDIV_LEVELS, written
// by the suite's pages study (verification/include/crossdiv/verification/suite/levels_page.h).
// window.crossdivLevels is the page's state, for the browser test.
(function () {
  "use strict";

  const data = window.CROSSDIV_LEVELS;
  const BACKGROUND = 0xf4f4f4;

  function bytes(b64) {
    const s = atob(b64), out = new Uint8Array(s.length);
    for (let i = 0; i < s.length; ++i) out[i] = s.charCodeAt(i);
    return out.buffer;
  }

  const entries = data.entries.map((e) => ({
    label: e.mesh + " · " + e.scheme + " (" + e.rule + ")",
    levels: e.levels.map((l) => ({positions: new Float64Array(bytes(l.positions)), triangles: new Int32Array(bytes(l.triangles)),
                                  edges: new Int32Array(bytes(l.edges)), faces: l.faces})),
  }));

  const view = document.getElementById("view");
  const renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
  renderer.setPixelRatio(1);
  renderer.setClearColor(BACKGROUND);
  renderer.setScissorTest(true);
  view.appendChild(renderer.domElement);
  const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1000);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.screenSpacePanning = true;
  controls.addEventListener("change", render);
  const state = {entry: 0, scenes: []};

  function lines(level, color) {
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(new Float32Array(level.positions), 3));
    g.setIndex(new THREE.BufferAttribute(new Uint32Array(level.edges), 1));
    return new THREE.LineSegments(g, new THREE.LineBasicMaterial({color}));
  }

  function surface(level, flat) {
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(new Float32Array(level.positions), 3));
    g.setIndex(new THREE.BufferAttribute(new Uint32Array(level.triangles), 1));
    g.computeVertexNormals();
    const m = new THREE.MeshPhongMaterial({color: 0x9fb7d0, flatShading: flat, side: THREE.DoubleSide,
                                           polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1});
    return new THREE.Mesh(g, m);
  }

  function build() {
    const e = entries[state.entry], flat = document.getElementById("flat").checked;
    state.scenes = e.levels.map((level) => {
      const scene = new THREE.Scene();
      scene.add(new THREE.AmbientLight(0xffffff, 0.35));
      // A headlight: render() points it along the view, whichever way the camera turns.
      scene.userData.light = new THREE.DirectionalLight(0xffffff, 0.75);
      scene.add(scene.userData.light);
      scene.add(surface(level, flat));
      if (document.getElementById("show-wire").checked) scene.add(lines(level, 0x303840));
      if (document.getElementById("show-net").checked) scene.add(lines(e.levels[0], 0x1060d0));
      return scene;
    });
    document.getElementById("captions").innerHTML = e.levels.map((l, i) =>
      `<div>level ${i}: ${l.positions.length / 3} vertices, ${l.faces} faces</div>`).join("");
    render();
  }

  function frame() {
    const p = entries[state.entry].levels[0].positions, lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < p.length; ++i) { lo[i % 3] = Math.min(lo[i % 3], p[i]); hi[i % 3] = Math.max(hi[i % 3], p[i]); }
    const c = lo.map((l, k) => (l + hi[k]) / 2), size = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) || 1;
    controls.target.set(c[0], c[1], c[2]);
    // Far enough that a ball of the mesh's size fits the view's narrower side.
    const n = entries[state.entry].levels.length, aspect = view.clientWidth / n / view.clientHeight;
    const fit = 0.6 * size / Math.tan(camera.fov * Math.PI / 360) / Math.min(1, aspect);
    const dir = new THREE.Vector3(1.3, 0.9, 1.6).normalize().multiplyScalar(fit);
    camera.position.set(c[0] + dir.x, c[1] + dir.y, c[2] + dir.z);
    camera.near = size / 100;
    camera.far = size * 100;
    controls.update();
  }

  function render() {
    const w = view.clientWidth, h = view.clientHeight, n = state.scenes.length || 1, cell = Math.floor(w / n);
    camera.aspect = cell / h;
    camera.updateProjectionMatrix();
    state.scenes.forEach((scene, i) => {
      scene.userData.light.position.copy(camera.position).sub(controls.target);  // shines towards its target, the origin
      renderer.setViewport(i * cell, 0, cell, h);
      renderer.setScissor(i * cell, 0, cell, h);
      renderer.render(scene, camera);
    });
  }

  function resize() {
    renderer.setSize(view.clientWidth, view.clientHeight);
    render();
  }

  const select = document.getElementById("entry");
  entries.forEach((e, i) => select.add(new Option(e.label, String(i))));
  select.addEventListener("change", () => { state.entry = Number(select.value); frame(); build(); });
  for (const id of ["show-net", "show-wire", "flat", "smooth"]) document.getElementById(id).addEventListener("change", build);
  window.addEventListener("resize", resize);
  renderer.setSize(view.clientWidth, view.clientHeight);
  frame();
  build();
  window.crossdivLevels = {state, entries, renderer, build, select: (i) => { select.value = String(i); select.dispatchEvent(new Event("change")); }};
})();
