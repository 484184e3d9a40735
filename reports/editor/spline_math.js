// The curve editor's spline arithmetic: every editable SWP record as a chain of cubic Bezier
// segments, built as core builds it (core/include/crossdiv/curves/cubic_spline.h), de Casteljau's
// levels, the uniform tessellation of `crossdiv tessellate --mode uniform` and the SWP text that
// core's reader takes back. A classic script (the page opens from disk, where ES modules may not
// load): it defines window.CrossdivSplines. Points are arrays [x, y, z].
(function () {
  "use strict";

  function lerp(a, b, t) {
    // (1 - t) a + t b, component by component: core's casteljau_step, so the levels agree bit for bit.
    return [(1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1], (1 - t) * a[2] + t * b[2]];
  }

  function combine(weights, points) {
    const out = [0, 0, 0];
    for (let i = 0; i < points.length; ++i)
      for (let k = 0; k < 3; ++k) out[k] += weights[i] * points[i][k];
    return out;
  }

  // B-spline window -> Bezier (Bohm): (p0 + 4 p1 + p2) / 6, (2 p1 + p2) / 3, (p1 + 2 p2) / 3, (p1 + 4 p2 + p3) / 6.
  function bsplineSegment(p) {
    return [combine([1 / 6, 4 / 6, 1 / 6], [p[0], p[1], p[2]]), combine([2 / 3, 1 / 3], [p[1], p[2]]),
            combine([1 / 3, 2 / 3], [p[1], p[2]]), combine([1 / 6, 4 / 6, 1 / 6], [p[1], p[2], p[3]])];
  }

  // Catmull-Rom window -> Bezier: p1, p1 + (p2 - p0) / 6, p2 - (p3 - p1) / 6, p2.
  function catmullRomSegment(p) {
    const d = (a, b, s) => [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]];
    const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    return [p[1].slice(), d(p[1], sub(p[2], p[0]), 1 / 6), d(p[2], sub(p[3], p[1]), -1 / 6), p[2].slice()];
  }

  // Every window of 4 consecutive points, `stride` apart (a Bezier chain's segments share their
  // ends: 3; a sliding window: 1), as Bezier segments by `convert`.
  function windows(p, stride, convert) {
    const out = [];
    for (let i = 0; i + 3 < p.length; i += stride) out.push(convert(p.slice(i, i + 4)));
    return out;
  }

  // The editable records by SWP keyword stem: what their counts must be, in words and as a test,
  // and their Bezier segments.
  const TYPES = {
    bez: {
      title: "Bezier chain", color: 0xf2d024,
      rule: "3n + 1 points (segments share their ends)",
      valid: (n) => n >= 4 && (n - 1) % 3 === 0,
      segments: (p) => windows(p, 3, (w) => w),
    },
    bsp: {
      title: "uniform cubic B-spline", color: 0x3cc864,
      rule: "at least 4 points (a sliding window of 4)",
      valid: (n) => n >= 4,
      segments: (p) => windows(p, 1, bsplineSegment),
    },
    crm: {
      title: "Catmull-Rom (open)", color: 0x40c0f0,
      rule: "at least 4 points (runs from the second to the last but one)",
      valid: (n) => n >= 4,
      segments: (p) => windows(p, 1, catmullRomSegment),
    },
    crc: {
      title: "Catmull-Rom (closed)", color: 0xf070c0,
      rule: "at least 3 points (through every point, wrapping around)",
      valid: (n) => n >= 3,
      segments: (p) => {
        // The window read cyclically from each point, as core's sliding_window: segment i runs
        // from p_{i+1} to p_{i+2}.
        const n = p.length, out = [];
        for (let i = 0; i < n; ++i)
          out.push(catmullRomSegment([p[i], p[(i + 1) % n], p[(i + 2) % n], p[(i + 3) % n]]));
        return out;
      },
    },
  };

  function stem(keyword) { return keyword.slice(0, 3); }
  function dimOf(keyword) { return keyword.endsWith("3") ? 3 : 2; }

  /// The complete segments of a curve {keyword, points}; none while its count is invalid.
  function segments(curve) {
    const type = TYPES[stem(curve.keyword)];
    return type.valid(curve.points.length) ? type.segments(curve.points) : [];
  }

  /// Every de Casteljau level of one segment at t (level 0 the control points, the last the point).
  function casteljau(control, t) {
    const levels = [control.map((p) => p.slice())];
    while (levels[levels.length - 1].length > 1) {
      const prev = levels[levels.length - 1], next = [];
      for (let i = 0; i + 1 < prev.length; ++i) next.push(lerp(prev[i], prev[i + 1], t));
      levels.push(next);
    }
    return levels;
  }

  /// `steps` intervals per segment at t = i / steps, and the chain's end: `crossdiv tessellate
  /// --mode uniform` (core's tessellate_uniform), as {points, params}.
  function tessellate(curve) {
    const segs = segments(curve), points = [], params = [];
    segs.forEach((s, k) => {
      for (let i = 0; i < curve.steps; ++i) {
        const t = i / curve.steps;
        const levels = casteljau(s, t);
        points.push(levels[3][0]);
        params.push(k + t);
      }
    });
    if (segs.length) {
      points.push(segs[segs.length - 1][3].slice());
      params.push(segs.length);
    }
    return {points, params};
  }

  /// What keeps a curve from being written: a wrong count or name, or a non-finite point; null when none.
  function problem(curve) {
    const type = TYPES[stem(curve.keyword)];
    if (!type) return "unknown keyword " + curve.keyword;
    if (!type.valid(curve.points.length)) return type.title + " needs " + type.rule + "; it has " + curve.points.length;
    if (!/^[^\s\[\]#]+$/.test(curve.name)) return "the name must be one word without brackets or #";
    if (!(Number.isInteger(curve.steps) && curve.steps >= 1 && curve.steps <= 1000000)) return "steps must be an integer in 1..1000000";
    for (const p of curve.points)
      if (!p.every(Number.isFinite)) return "a point is not finite";
    return null;
  }

  /// A curve as an SWP record. JavaScript writes a number as the shortest text that reads back
  /// to the same double, so core's reader gets every coordinate bit for bit.
  function swpRecord(curve) {
    const dim = dimOf(curve.keyword);
    const pts = curve.points.map((p) => "[" + p.slice(0, dim).map((x) => String(x)).join(" ") + "]");
    return curve.keyword + " " + curve.name + " " + curve.steps + " " + curve.points.length + " " + pts.join(" ");
  }

  /// The whole file, or {error} naming the first curve that cannot be written.
  function swp(curves) {
    const lines = ["# written by crossdiv's curve editor"];
    for (let i = 0; i < curves.length; ++i) {
      const why = problem(curves[i]);
      if (why) return {error: "curve " + (i + 1) + " (" + curves[i].keyword + " " + curves[i].name + "): " + why};
      lines.push(swpRecord(curves[i]));
    }
    const names = new Set();
    for (const c of curves) {
      if (c.name !== "." && names.has(c.name)) return {error: "two curves are named " + c.name};
      names.add(c.name);
    }
    return {text: lines.join("\n") + "\n"};
  }

  window.CrossdivSplines = {TYPES, stem, dimOf, segments, casteljau, tessellate, problem, swp};
})();
