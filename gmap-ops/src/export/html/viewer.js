// gmap view: a small WebGL 2 renderer for one map or cell complex (no library, nothing
// fetched). The data come from the page's <script> elements: `gmap-meta` (JSON) and base64
// little-endian arrays (`gmap-alpha`, `gmap-points`, …). Everything else (cells, centres,
// exploded darts) is computed here. Written by gmap-ops/src/export/html; see its docs.
(function () {
  'use strict';
  const T0 = performance.now();
  const $ = (id) => document.getElementById(id);
  const meta = JSON.parse($('gmap-meta').textContent);
  const marks = {};
  const mark = (name) => { marks[name] = Math.round(performance.now()); };

  function blob(name, Type) {
    const el = $('gmap-' + name);
    if (!el) return null;
    const s = atob(el.textContent);
    const b = new Uint8Array(s.length);
    for (let i = 0; i < s.length; i++) b[i] = s.charCodeAt(i);
    return new Type(b.buffer);
  }

  // ---------------------------------------------------------------- colours
  const ALPHA_COLOURS = ['#d62728', '#2ca02c', '#1f77b4', '#ff7f0e', '#9467bd', '#17becf', '#8c564b', '#e377c2', '#bcbd22', '#7f7f7f'];
  const PALETTE = ['#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f', '#edc948', '#b07aa1', '#ff9da7', '#9c755f', '#bab0ac',
    '#1b9e77', '#d95f02', '#7570b3', '#e7298a', '#66a61e', '#e6ab02', '#a6761d', '#8dd3c7', '#bebada', '#fb8072'];
  const GEN_COLOURS = ['#e6194b', '#3cb44b', '#4363d8', '#f58231', '#911eb4', '#42d4f4', '#f032e6', '#9a6324', '#469990', '#800000'];
  const FREE_COLOUR = '#ff00cc', DART_COLOUR = '#303030', NONE_COLOUR = '#d0d0d0', SELECT_COLOUR = '#ffd400';
  const BG = [0.969, 0.969, 0.957];
  function rgb(hex) { const v = parseInt(hex.slice(1), 16); return [(v >> 16) & 255, (v >> 8) & 255, v & 255]; }
  function hsl(h, s, l) {
    const f = (n) => { const k = (n + h * 12) % 12; return l - s * Math.min(l, 1 - l) * Math.max(-1, Math.min(k - 3, 9 - k, 1)); };
    return [Math.round(f(0) * 255), Math.round(f(8) * 255), Math.round(f(4) * 255)];
  }
  const CATEGORY = [];
  function category(k) { while (CATEGORY.length <= k) { const j = CATEGORY.length; CATEGORY.push(j < PALETTE.length ? rgb(PALETTE[j]) : hsl((j * 0.618034) % 1, 0.55, 0.55)); } return CATEGORY[k]; }
  function genColour(k) { return k < GEN_COLOURS.length ? rgb(GEN_COLOURS[k]) : hsl((k * 0.618034 + 0.3) % 1, 0.8, 0.45); }
  const css = (c) => 'rgb(' + c[0] + ',' + c[1] + ',' + c[2] + ')';

  // ---------------------------------------------------------------- page
  const side = document.createElement('div');
  side.id = 'side';
  side.innerHTML =
    '<h1 id="title"></h1><div id="summary" class="small"></div>' +
    '<div class="row" id="views"><button data-view="darts">darts</button><button data-view="cells">cells</button><button data-view="homology">homology</button></div>' +
    '<div id="message"></div>' +
    '<div class="row" id="explode-row">explode <input type="range" id="explode" min="0" max="100" value="0"></div>' +
    '<div class="row" id="colorby-row">colour by <select id="colorby"></select></div>' +
    '<div id="legend-box"><h2>legend</h2><div id="legend-darts"></div><div id="legend-cells"></div></div>' +
    '<div id="gen-box"><h2>generators</h2><div id="generators"></div></div>' +
    '<h2>selection</h2><div id="selection" class="small">click a dart (or a cell)</div><div id="sel-buttons"></div>' +
    '<h2>about this drawing</h2><div id="notes" class="small"></div>' +
    '<div class="small" id="help" style="margin-top:8px">drag: rotate · right-drag or shift-drag: pan · wheel: zoom · click: select · keys 0…9: highlight the selected dart\'s i-cell · Esc: clear</div>';
  document.body.appendChild(side);
  const canvas = document.createElement('canvas');
  canvas.id = 'gl';
  document.body.appendChild(canvas);
  const selftestOut = document.createElement('pre');
  selftestOut.id = 'selftest';
  document.body.appendChild(selftestOut);

  $('title').textContent = meta.title;
  const isMap = meta.kind === 'map';
  const n = meta.dim, w = n + 1, N = meta.darts;
  {
    const parts = [];
    if (isMap) parts.push(n + '-map, ' + N.toLocaleString('en') + ' darts');
    else parts.push(n + '-dimensional complex (no darts)');
    parts.push('cells per dimension: ' + meta.counts.map((c, i) => i + ': ' + c.toLocaleString('en')).join(', '));
    $('summary').textContent = parts.join('; ');
    const notes = ['Positions: ' + meta.placement + '.'];
    if (meta.rule) notes.push(meta.rule);
    for (const x of meta.notes) notes.push(x);
    notes.push('Darts view: each dart is a segment from near its vertex towards the middle of its edge, pulled towards the centres of its face and volume; connectors show αi, one colour per i.');
    $('notes').innerHTML = notes.map((t) => '<p>' + t.replace(/&/g, '&amp;').replace(/</g, '&lt;') + '</p>').join('');
  }
  function message(text) { const m = $('message'); m.textContent = text || ''; m.style.display = text ? 'block' : 'none'; }

  // ---------------------------------------------------------------- labels
  // labels[i]: Map cell -> [[name, [text, kind]], ...]
  const labels = meta.labels.map((per) => new Map(per.map(([c, l]) => [c, l])));
  const labelDims = {};
  meta.labels.forEach((per, i) => per.forEach(([, l]) => l.forEach(([name]) => {
    (labelDims[name] = labelDims[name] || new Set()).add(i);
  })));
  function labelOf(i, c, name) {
    const l = labels[i] && labels[i].get(c);
    if (!l) return null;
    for (const [k, v] of l) if (k === name) return v;
    return null;
  }
  function labelText(i, c) {
    const l = labels[i] && labels[i].get(c);
    return l ? l.map(([k, v]) => k + '=' + (v[1] === 'text' ? JSON.stringify(v[0]) : v[0])).join(' ') : '';
  }

  // ---------------------------------------------------------------- data
  const P = blob('points', Float32Array);
  // alpha: per dart and involution, alpha_i(d) - d zigzag-encoded as a LEB128 varint
  function decodeAlpha() {
    const el = $('gmap-alpha'), s = atob(el.textContent), out = new Uint32Array(N * w);
    let p = 0, k = 0;
    for (let d = 0; d < N; d++) {
      for (let i = 0; i < w; i++, k++) {
        let b = s.charCodeAt(p++), x = b & 127, m = 128;
        while (b & 128) { b = s.charCodeAt(p++); x += (b & 127) * m; m *= 128; }
        out[k] = d + (x % 2 === 1 ? -(x + 1) / 2 : x / 2);
      }
    }
    return out;
  }
  const A = isMap ? decodeAlpha() : null;
  mark('decoded');

  // orbits of the involutions in `mask` (bit i for alpha_i), numbered by smallest dart as
  // DenseMap::partition does; cached
  const orbitCache = new Map();
  function orbit(mask) {
    if (orbitCache.has(mask)) return orbitCache.get(mask);
    let top = -1;
    for (let i = 0; i <= n; i++) if (mask & (1 << i)) top = i;
    const id = new Int32Array(N);
    let count = 0;
    if (top < 0 || (mask & ~(1 << top)) === 0) {
      // one involution (or none): its pairs, numbered by smaller dart
      for (let d = 0; d < N; d++) { const e = top < 0 ? d : A[d * w + top]; id[d] = e < d ? id[e] : count++; }
    } else {
      // the orbits without the highest involution, joined along it: a union-find over
      // those orbits (fewer than the darts), union by smallest root, path halving
      const sub = orbit(mask & ~(1 << top)), sid = sub.id, parent = new Int32Array(sub.count);
      for (let x = 0; x < sub.count; x++) parent[x] = x;
      for (let d = 0; d < N; d++) {
        let a = sid[d], b = sid[A[d * w + top]];
        if (a === b) continue;
        while (parent[a] !== a) { parent[a] = parent[parent[a]]; a = parent[a]; }
        while (parent[b] !== b) { parent[b] = parent[parent[b]]; b = parent[b]; }
        if (a < b) parent[b] = a; else if (b < a) parent[a] = b;
      }
      // sub-orbits are numbered by smallest dart, so the root of a set holds its smallest
      // dart, met first in dart order
      const label = new Int32Array(sub.count).fill(-1);
      for (let d = 0; d < N; d++) {
        let r = sid[d];
        while (parent[r] !== r) r = parent[r];
        if (label[r] < 0) label[r] = count++;
        id[d] = label[r];
      }
    }
    const o = { id, count };
    orbitCache.set(mask, o);
    return o;
  }
  const ALL = (1 << w) - 1;
  const cellsOf = (i) => orbit(ALL & ~(1 << i));
  function centres(o, pos) {
    const c = new Float64Array(o.count * 3), k = new Float64Array(o.count);
    for (let d = 0; d < N; d++) {
      const x = o.id[d];
      c[3 * x] += pos[3 * d]; c[3 * x + 1] += pos[3 * d + 1]; c[3 * x + 2] += pos[3 * d + 2]; k[x]++;
    }
    const out = new Float32Array(o.count * 3);
    for (let x = 0; x < o.count; x++) for (let a = 0; a < 3; a++) out[3 * x + a] = c[3 * x + a] / Math.max(k[x], 1);
    return out;
  }

  // per-dart vertex position VP and edge point MP; the orbit levels <a0..a(k-1)>, k = 2..n
  let VP = null, MP = null, levels = [], HF = null, HFC = null, UNIT = null, UNITC = null;
  if (isMap) {
    VP = new Float32Array(N * 3);
    MP = new Float32Array(N * 3);
    const v0 = cellsOf(0).id;
    const nv = meta.counts[0];
    const e1 = meta.edgePoints && n >= 1 ? cellsOf(1).id : null;
    mark('cells0');
    for (let d = 0; d < N; d++) { const p = 3 * v0[d]; VP[3 * d] = P[p]; VP[3 * d + 1] = P[p + 1]; VP[3 * d + 2] = P[p + 2]; }
    for (let d = 0; d < N; d++) {
      if (e1) {
        const p = 3 * (nv + e1[d]);
        MP[3 * d] = P[p]; MP[3 * d + 1] = P[p + 1]; MP[3 * d + 2] = P[p + 2];
      } else {
        const e = n >= 1 ? A[d * w] : d;
        for (let a = 0; a < 3; a++) MP[3 * d + a] = 0.5 * (VP[3 * d + a] + VP[3 * e + a]);
      }
    }
    mark('edgepoints');
    for (let k = 2; k <= n; k++) {
      const o = orbit((1 << k) - 1);
      mark('orbit' + k);
      levels.push({ k, o, c: centres(o, MP) });
      mark('centres' + k);
    }
    if (levels.length) {
      HF = levels[0].o; HFC = levels[0].c;
      UNIT = levels[levels.length - 1].o; UNITC = levels[levels.length - 1].c;
    }
  }

  mark('orbits');

  // the complex: primitives and cells
  let CX = null;
  if (!isMap) {
    CX = {
      tri: blob('tri', Uint32Array), triCell: blob('triCell', Uint32Array),
      seg: blob('seg', Uint32Array), segCell: blob('segCell', Uint32Array),
      dot: blob('dot', Uint32Array), dotCell: blob('dotCell', Uint32Array),
      cellDim: blob('cellDim', Uint8Array), cellShown: blob('cellShown', Uint8Array), link: blob('link', Uint32Array),
    };
    const nc = CX.cellDim.length;
    CX.index = new Int32Array(nc); // number within its dimension
    CX.global = meta.counts.map(() => []);
    for (let g = 0; g < nc; g++) { CX.index[g] = CX.global[CX.cellDim[g]].length; CX.global[CX.cellDim[g]].push(g); }
    const sum = new Float64Array(nc * 3), cnt = new Float64Array(nc);
    const add = (g, p) => { sum[3 * g] += P[3 * p]; sum[3 * g + 1] += P[3 * p + 1]; sum[3 * g + 2] += P[3 * p + 2]; cnt[g]++; };
    for (let t = 0; t < CX.triCell.length; t++) for (let j = 0; j < 3; j++) add(CX.triCell[t], CX.tri[3 * t + j]);
    for (let s = 0; s < CX.segCell.length; s++) for (let j = 0; j < 2; j++) add(CX.segCell[s], CX.seg[2 * s + j]);
    for (let s = 0; s < CX.dotCell.length; s++) add(CX.dotCell[s], CX.dot[s]);
    CX.centre = new Float32Array(nc * 3);
    for (let g = 0; g < nc; g++) for (let a = 0; a < 3; a++) CX.centre[3 * g + a] = sum[3 * g + a] / Math.max(cnt[g], 1);
  }

  // the scene's box
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let p = 0; p < P.length; p += 3) for (let a = 0; a < 3; a++) { lo[a] = Math.min(lo[a], P[p + a]); hi[a] = Math.max(hi[a], P[p + a]); }
  if (!(lo[0] <= hi[0])) { lo.fill(-1); hi.fill(1); }
  const MID = [0, 1, 2].map((a) => 0.5 * (lo[a] + hi[a]));
  const RADIUS = Math.max(1e-6, 0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));

  // ---------------------------------------------------------------- WebGL
  const gl = canvas.getContext('webgl2', { antialias: N <= meta.dartLimit && P.length < 3e6, preserveDrawingBuffer: true });
  if (!gl) { message('This browser offers no WebGL 2: nothing can be drawn.'); throw new Error('no WebGL 2'); }
  function shader(type, src) {
    const s = gl.createShader(type);
    gl.shaderSource(s, src);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  }
  function program(vs, fs) {
    const p = gl.createProgram();
    gl.attachShader(p, shader(gl.VERTEX_SHADER, vs));
    gl.attachShader(p, shader(gl.FRAGMENT_SHADER, fs));
    gl.bindAttribLocation(p, 0, 'aPos'); gl.bindAttribLocation(p, 1, 'aCtr'); gl.bindAttribLocation(p, 2, 'aCol'); gl.bindAttribLocation(p, 3, 'aOther');
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
    const u = {};
    for (let i = 0; i < gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS); i++) { const name = gl.getActiveUniform(p, i).name; u[name] = gl.getUniformLocation(p, name); }
    return { p, u };
  }
  const VS = `#version 300 es
    layout(location=0) in vec3 aPos; layout(location=1) in vec3 aCtr; layout(location=2) in vec4 aCol;
    uniform mat4 uMvp; uniform mat4 uView; uniform float uExplode; uniform vec3 uMid; uniform float uSize;
    out vec4 vCol; out vec3 vEye;
    void main() { vec3 p = aPos + uExplode * (aCtr - uMid); gl_Position = uMvp * vec4(p, 1.0); vEye = (uView * vec4(p, 1.0)).xyz; vCol = aCol; gl_PointSize = uSize; }`;
  const FS_FLAT = `#version 300 es
    precision highp float; in vec4 vCol; in vec3 vEye; uniform float uFade; uniform float uAlpha; out vec4 o;
    void main() { o = vec4(mix(vCol.rgb, vec3(1.0), uFade), vCol.a * uAlpha); }`;
  const FS_LIT = `#version 300 es
    precision highp float; in vec4 vCol; in vec3 vEye; uniform float uFade; uniform float uAlpha; out vec4 o;
    void main() { vec3 nrm = normalize(cross(dFdx(vEye), dFdy(vEye))); float l = 0.45 + 0.55 * abs(nrm.z);
      o = vec4(mix(vCol.rgb, vec3(0.86), uFade) * l, vCol.a * uAlpha); }`;
  const VS_THICK = `#version 300 es
    layout(location=0) in vec3 aPos; layout(location=3) in vec4 aOther; layout(location=2) in vec4 aCol;
    uniform mat4 uMvp; uniform vec2 uViewport; uniform float uWidth; out vec4 vCol; out vec3 vEye;
    void main() { vec4 c = uMvp * vec4(aPos, 1.0); vec4 q = uMvp * vec4(aOther.xyz, 1.0);
      vec2 a = c.xy / c.w * uViewport, b = q.xy / q.w * uViewport; vec2 d = b - a;
      d = length(d) > 1e-6 ? normalize(d) : vec2(1.0, 0.0);
      vec2 off = vec2(-d.y, d.x) * aOther.w * uWidth;
      gl_Position = vec4(c.xy + off / uViewport * c.w, c.z - 0.002 * c.w, c.w); vCol = aCol; vEye = vec3(0.0); }`;
  const progLit = program(VS, FS_LIT), progFlat = program(VS, FS_FLAT), progThick = program(VS_THICK, FS_FLAT);

  // a drawable: {mode, count, vao, indexed, prog, colour (when no per-vertex colour), size, thick}
  function drawable(mode, arrays, opts) {
    opts = opts || {};
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const attr = (loc, data, size, type, norm) => {
      const b = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, b);
      gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, size, type, norm, 0, 0);
      return b;
    };
    attr(0, arrays.pos, 3, gl.FLOAT, false);
    if (arrays.ctr) attr(1, arrays.ctr, 3, gl.FLOAT, false);
    const d = { mode, vao, prog: opts.prog || progFlat, colour: opts.colour || [0, 0, 0], size: opts.size || 1, alpha: 1 };
    if (arrays.col) { d.colBuf = attr(2, arrays.col, 4, gl.UNSIGNED_BYTE, true); }
    if (arrays.other) attr(3, arrays.other, 4, gl.FLOAT, false);
    if (arrays.index) {
      const b = gl.createBuffer();
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, b);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, arrays.index, gl.STATIC_DRAW);
      d.indexed = true; d.count = arrays.index.length;
    } else d.count = arrays.pos.length / 3;
    d.hasCtr = !!arrays.ctr; d.hasCol = !!arrays.col;
    gl.bindVertexArray(null);
    return d;
  }
  function setColours(d, col) { gl.bindBuffer(gl.ARRAY_BUFFER, d.colBuf); gl.bufferData(gl.ARRAY_BUFFER, col, gl.STATIC_DRAW); }

  // thick lines: segments [x0 y0 z0 x1 y1 z1 ...] become two triangles each
  function thickLines(segs, colour, width) {
    const m = segs.length / 6, pos = new Float32Array(m * 18), other = new Float32Array(m * 24);
    const corner = [[0, 1], [0, -1], [1, -1], [1, -1], [0, -1], [1, 1]];
    for (let s = 0; s < m; s++) {
      for (let k = 0; k < 6; k++) {
        const [end, side] = corner[k], me = 6 * s + 3 * end, it = 6 * s + 3 * (1 - end), v = 6 * s + k;
        for (let a = 0; a < 3; a++) { pos[3 * v + a] = segs[me + a]; other[4 * v + a] = segs[it + a]; }
        other[4 * v + 3] = end === 0 ? side : -side;
      }
    }
    return drawable(gl.TRIANGLES, { pos, other }, { prog: progThick, colour, size: width });
  }

  // ---------------------------------------------------------------- camera
  const cam = { yaw: -0.95, pitch: 0.42, dist: RADIUS * 3.2, target: MID.slice() };
  let view = null, proj = null, mvp = null, explode = 0;
  function mat4mul(a, b) {
    const o = new Float32Array(16);
    for (let c = 0; c < 4; c++) for (let r = 0; r < 4; r++) {
      let s = 0;
      for (let k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
      o[c * 4 + r] = s;
    }
    return o;
  }
  function updateCamera() {
    const cp = Math.cos(cam.pitch), eye = [cam.target[0] + cam.dist * cp * Math.cos(cam.yaw), cam.target[1] + cam.dist * cp * Math.sin(cam.yaw), cam.target[2] + cam.dist * Math.sin(cam.pitch)];
    const f = [cam.target[0] - eye[0], cam.target[1] - eye[1], cam.target[2] - eye[2]];
    const fl = Math.hypot(...f); f[0] /= fl; f[1] /= fl; f[2] /= fl;
    const up = [0, 0, 1];
    let s = [f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]];
    const sl = Math.hypot(...s) || 1; s = s.map((x) => x / sl);
    const u = [s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]];
    view = new Float32Array([s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0,
      -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]), -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]), f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2], 1]);
    cam.right = s; cam.up = u;
    const aspect = canvas.width / Math.max(canvas.height, 1), fov = 35 * Math.PI / 180, t = 1 / Math.tan(fov / 2);
    const near = Math.max(cam.dist - RADIUS * 3, cam.dist * 0.01), far = cam.dist + RADIUS * 3;
    proj = new Float32Array([t / aspect, 0, 0, 0, 0, t, 0, 0, 0, 0, (far + near) / (near - far), -1, 0, 0, 2 * far * near / (near - far), 0]);
    mvp = mat4mul(proj, view);
  }

  // ---------------------------------------------------------------- views
  const state = { view: null, colorBy: null, gens: meta.generators.map(() => true), selected: -1, highlight: -1 };
  let dartsView = null, cellsView = null, genViews = [], selectionView = [];

  // the darts view: kept darts (thinned above the limit), their segments, connectors, free marks
  let DT = null, kept = null;
  function buildDarts() {
    const limit = meta.dartLimit;
    let step = 1;
    if (N > limit) step = Math.ceil(N / limit);
    kept = [];
    for (let d = 0; d < N; d++) if (step === 1 || (UNIT ? UNIT.id[d] : d) % step === 0) kept.push(d);
    kept = Uint32Array.from(kept);
    DT = new Float32Array(N * 6);
    const pull = [0.2, 0.14, 0.1];
    for (const d of kept) {
      for (let e = 0; e < 2; e++) {
        const t = e === 0 ? 0.1 : 0.8;
        const x = [0, 1, 2].map((a) => VP[3 * d + a] + t * (MP[3 * d + a] - VP[3 * d + a]));
        levels.forEach((L, j) => {
          const c = 3 * L.o.id[d], f = pull[Math.min(j, 2)];
          for (let a = 0; a < 3; a++) x[a] += f * (L.c[c + a] - x[a]);
        });
        for (let a = 0; a < 3; a++) DT[6 * d + 3 * e + a] = x[a];
      }
    }
    const seg = new Float32Array(kept.length * 6);
    kept.forEach((d, k) => seg.set(DT.subarray(6 * d, 6 * d + 6), 6 * k));
    const at = (d, t, out, o) => { for (let a = 0; a < 3; a++) out[o + a] = DT[6 * d + a] + t * (DT[6 * d + 3 + a] - DT[6 * d + a]); };
    const keptMask = new Uint8Array(N);
    for (const d of kept) keptMask[d] = 1;
    const conns = [];
    for (let i = 0; i <= n; i++) {
      const t = i === 0 ? 0.92 : i === 1 ? 0.08 : 0.5;
      const pts = [];
      for (const d of kept) { const e = A[d * w + i]; if (e > d && keptMask[e]) pts.push(d, e); }
      const pos = new Float32Array(pts.length * 3);
      for (let k = 0; k < pts.length; k++) at(pts[k], t, pos, 3 * k);
      conns.push(drawable(gl.LINES, { pos }, { colour: rgb(ALPHA_COLOURS[i % ALPHA_COLOURS.length]) }));
    }
    const free = [];
    for (const d of kept) for (let i = 0; i <= n; i++) if (A[d * w + i] === d) { free.push(d); break; }
    const fp = new Float32Array(free.length * 3);
    free.forEach((d, k) => at(d, 0.5, fp, 3 * k));
    dartsView = { darts: drawable(gl.LINES, { pos: seg }, { colour: rgb(DART_COLOUR) }), conns, free: drawable(gl.POINTS, { pos: fp }, { colour: rgb(FREE_COLOUR), size: 5 }), freeCount: free.length };
    const lg = $('legend-darts');
    let h = '<div class="legend-item"><span class="swatch" style="background:' + DART_COLOUR + '"></span>dart</div>';
    for (let i = 0; i <= n; i++) h += '<div class="legend-item"><span class="swatch" style="background:' + ALPHA_COLOURS[i % ALPHA_COLOURS.length] + '"></span>α' + i + ' link</div>';
    h += '<div class="legend-item"><span class="swatch" style="background:' + FREE_COLOUR + '"></span>free dart (αi(d) = d for some i): ' + free.length.toLocaleString('en') + '</div>';
    lg.innerHTML = h;
  }

  // the cells view of a map: faces fanned from their centres, per-vertex explode centre
  function buildMapCells() {
    if (!HF) return null;
    const ep = meta.edgePoints;
    const nvx = (ep ? 2 * N : N) + HF.count;
    const pos = new Float32Array(nvx * 3), ctr = new Float32Array(nvx * 3);
    pos.set(VP, 0);
    if (ep) pos.set(MP, 3 * N);
    const c0 = ep ? 2 * N : N;
    pos.set(HFC, 3 * c0);
    const unitOf = (d) => UNIT.id[d];
    for (let d = 0; d < N; d++) {
      const u = 3 * unitOf(d);
      for (let a = 0; a < 3; a++) { ctr[3 * d + a] = UNITC[u + a]; if (ep) ctr[3 * (N + d) + a] = UNITC[u + a]; }
    }
    const seen = new Uint8Array(HF.count);
    for (let d = 0; d < N; d++) {
      const h = HF.id[d];
      if (seen[h]) continue;
      seen[h] = 1;
      const u = 3 * unitOf(d);
      for (let a = 0; a < 3; a++) ctr[3 * (c0 + h) + a] = UNITC[u + a];
    }
    let m = 0;
    for (let d = 0; d < N; d++) if (ep || A[d * w] > d) m++;
    const tri = new Uint32Array(3 * m), line = new Uint32Array(2 * m);
    for (let d = 0, t = 0; d < N; d++) {
      const e = ep ? N + d : A[d * w];
      if (!ep && e <= d) continue;
      tri[3 * t] = c0 + HF.id[d]; tri[3 * t + 1] = d; tri[3 * t + 2] = e;
      line[2 * t] = d; line[2 * t + 1] = e;
      t++;
    }
    const col = new Uint8Array(nvx * 4);
    const faces = drawable(gl.TRIANGLES, { pos, ctr, col, index: tri }, { prog: progLit });
    const outline = N <= meta.dartLimit ? drawable(gl.LINES, { pos, ctr, index: line }, { colour: [60, 60, 60] }) : null;
    // colour of vertex v: from a dart of it
    const dartOfVertex = (v) => (v < N ? v : ep && v < 2 * N ? v - N : -1);
    const hfDart = new Int32Array(HF.count);
    for (let d = N - 1; d >= 0; d--) hfDart[HF.id[d]] = d;
    return { faces, outline, col, nvx, dartOf: (v) => { const d = dartOfVertex(v); return d >= 0 ? d : hfDart[v - c0]; } };
  }

  // the cells view of a complex: shown cells' primitives, links
  function buildComplexCells() {
    const shownTris = [], shownSegs = [], shownDots = [];
    for (let t = 0; t < CX.triCell.length; t++) if (CX.cellShown[CX.triCell[t]]) shownTris.push(t);
    for (let s = 0; s < CX.segCell.length; s++) if (CX.cellShown[CX.segCell[s]]) shownSegs.push(s);
    for (let s = 0; s < CX.dotCell.length; s++) if (CX.cellShown[CX.dotCell[s]]) shownDots.push(s);
    const make = (list, k, idx, cellArr, mode, prog, size) => {
      const pos = new Float32Array(list.length * k * 3), ctr = new Float32Array(list.length * k * 3), cells = new Uint32Array(list.length * k);
      list.forEach((t, j) => {
        for (let v = 0; v < k; v++) {
          const p = idx[k * t + v], g = cellArr[t], o = 3 * (k * j + v);
          for (let a = 0; a < 3; a++) { pos[o + a] = P[3 * p + a]; ctr[o + a] = CX.centre[3 * g + a]; }
          cells[k * j + v] = g;
        }
      });
      const col = new Uint8Array(list.length * k * 4);
      return { d: drawable(mode, { pos, ctr, col }, { prog, size }), cells, col };
    };
    const parts = [make(shownTris, 3, CX.tri, CX.triCell, gl.TRIANGLES, progLit, 1), make(shownSegs, 2, CX.seg, CX.segCell, gl.LINES, progFlat, 1),
      make(shownDots, 1, CX.dot, CX.dotCell, gl.POINTS, progFlat, 9)];
    const lp = new Float32Array(CX.link.length * 3);
    for (let k = 0; k < CX.link.length; k++) for (let a = 0; a < 3; a++) lp[3 * k + a] = P[3 * CX.link[k] + a];
    return { parts, links: drawable(gl.LINES, { pos: lp }, { colour: [150, 150, 150] }) };
  }

  // colouring: the chosen label, or one colour per top cell
  const colorSel = $('colorby');
  {
    const names = Object.keys(labelDims);
    let h = '<option value="">(one colour per ' + (isMap ? 'volume side' : 'cell') + ')</option>';
    for (const name of names) h += '<option value="' + name.replace(/"/g, '&quot;') + '">' + name.replace(/</g, '&lt;') + ' (' + [...labelDims[name]].sort().join(', ') + '-cells)</option>';
    colorSel.innerHTML = h;
  }
  function naturalSort(vals) {
    return vals.sort((a, b) => {
      const x = parseFloat(a), y = parseFloat(b);
      if (!isNaN(x) && !isNaN(y) && x !== y) return x - y;
      return a < b ? -1 : a > b ? 1 : 0;
    });
  }
  function colourCells() {
    const name = state.colorBy;
    const dims = name ? [...(labelDims[name] || [])].sort((a, b) => b - a) : [];
    // values -> colours
    const values = new Set();
    if (name) for (const k of dims) for (const [c] of labels[k]) { const v = labelOf(k, c, name); if (v) values.add(v[0]); }
    const order = naturalSort([...values]);
    const colourOf = new Map(order.map((v, k) => [v, category(k)]));
    const none = rgb(NONE_COLOUR);
    const lg = $('legend-cells');
    let h = '';
    if (name) {
      h += '<div class="small">' + name.replace(/</g, '&lt;') + ' of the ' + dims.join(', ') + '-cells</div>';
      for (const v of order) h += '<div class="legend-item"><span class="swatch" style="background:' + css(colourOf.get(v)) + '"></span>' + v.replace(/&/g, '&amp;').replace(/</g, '&lt;') + '</div>';
      h += '<div class="legend-item"><span class="swatch" style="background:' + NONE_COLOUR + '"></span>(no value)</div>';
    } else h += '<div class="small">one colour per ' + (isMap ? 'side of a top cell (orbit <α0…α' + (n - 1) + '>)' : 'cell') + '</div>';
    lg.innerHTML = h;
    if (isMap && cellsView) {
      category(996);
      const k = dims.find((x) => x >= 2);
      const ids = k !== undefined ? cellsOf(k).id : null;
      const col = cellsView.col;
      const cache = new Map();
      for (let v = 0; v < cellsView.nvx; v++) {
        const d = cellsView.dartOf(v);
        let c;
        if (ids) {
          const cell = ids[d];
          c = cache.get(cell);
          if (!c) { const lv = labelOf(k, cell, name); c = lv ? colourOf.get(lv[0]) : none; cache.set(cell, c); }
        } else if (name) c = none;
        else c = CATEGORY[UNIT.id[d] % 997];
        col[4 * v] = c[0]; col[4 * v + 1] = c[1]; col[4 * v + 2] = c[2]; col[4 * v + 3] = 255;
      }
      setColours(cellsView.faces, col);
      // labels of vertices and edges: marks on top
      cellsView.marks = [];
      for (const kk of dims.filter((x) => x < 2)) {
        const byColour = new Map();
        const o = cellsOf(kk).id, done = new Set();
        for (let d = 0; d < N; d++) {
          const cell = o[d];
          if (done.has(cell)) continue;
          done.add(cell);
          const lv = labelOf(kk, cell, name);
          if (!lv) continue;
          const key = lv[0];
          if (!byColour.has(key)) byColour.set(key, []);
          const L = byColour.get(key);
          if (kk === 0) L.push(VP[3 * d], VP[3 * d + 1], VP[3 * d + 2]);
          else { const e = A[d * w]; L.push(...VP.subarray(3 * d, 3 * d + 3), ...MP.subarray(3 * d, 3 * d + 3), ...MP.subarray(3 * d, 3 * d + 3), ...VP.subarray(3 * e, 3 * e + 3)); }
        }
        for (const [key, L] of byColour) {
          const arr = Float32Array.from(L);
          cellsView.marks.push(kk === 0 ? drawable(gl.POINTS, { pos: arr }, { colour: colourOf.get(key), size: 9 }) : thickLines(arr, colourOf.get(key), 3));
        }
      }
    } else if (!isMap && cellsView) {
      for (const part of cellsView.parts) {
        for (let v = 0; v < part.cells.length; v++) {
          const g = part.cells[v], k = CX.cellDim[g], lv = name ? labelOf(k, CX.index[g], name) : null;
          const c = lv ? colourOf.get(lv[0]) : name ? none : category(CX.index[g] % 997);
          part.col.set([c[0], c[1], c[2], 255], 4 * v);
        }
        setColours(part.d, part.col);
      }
    }
  }

  // overlays of cells: the k-cells marked in `mark` (a Set of cell numbers), in a colour
  function cellOverlay(k, mark, colour) {
    const out = [];
    if (isMap) {
      const ids = cellsOf(k).id, tri = [], seg = [], pts = [], first = new Set();
      for (let d = 0; d < N; d++) {
        const c = ids[d];
        if (!mark.has(c)) continue;
        if (k === 0) { if (!first.has(c)) { first.add(c); pts.push(VP[3 * d], VP[3 * d + 1], VP[3 * d + 2]); } }
        else if (k === 1) {
          if (!first.has(c)) {
            first.add(c);
            const e = n >= 1 ? A[d * w] : d;
            seg.push(...VP.subarray(3 * d, 3 * d + 3), ...MP.subarray(3 * d, 3 * d + 3), ...MP.subarray(3 * d, 3 * d + 3), ...VP.subarray(3 * e, 3 * e + 3));
          }
        } else if (HF) {
          const h = 3 * HF.id[d], u = 3 * UNIT.id[d];
          tri.push(HFC[h], HFC[h + 1], HFC[h + 2], ...VP.subarray(3 * d, 3 * d + 3), ...MP.subarray(3 * d, 3 * d + 3));
          for (let j = 0; j < 3; j++) tri.push(UNITC[u], UNITC[u + 1], UNITC[u + 2]);
        }
      }
      if (pts.length) out.push(drawable(gl.POINTS, { pos: Float32Array.from(pts) }, { colour, size: 12 }));
      if (seg.length) out.push(thickLines(Float32Array.from(seg), colour, 6));
      if (tri.length) {
        const m = tri.length / 18, pos = new Float32Array(m * 9), ctr = new Float32Array(m * 9);
        for (let t = 0; t < m; t++) { pos.set(tri.slice(18 * t, 18 * t + 9), 9 * t); ctr.set(tri.slice(18 * t + 9, 18 * t + 18), 9 * t); }
        const d = drawable(gl.TRIANGLES, { pos, ctr }, { prog: progLit, colour });
        d.offset = true;
        out.push(d);
      }
    } else {
      const globals = new Set([...mark].map((c) => CX.global[k][c]));
      const tri = [], ctr = [], seg = [], pts = [];
      for (let t = 0; t < CX.triCell.length; t++) {
        const g = CX.triCell[t];
        if (!globals.has(g)) continue;
        for (let j = 0; j < 3; j++) { const p = CX.tri[3 * t + j]; tri.push(P[3 * p], P[3 * p + 1], P[3 * p + 2]); ctr.push(CX.centre[3 * g], CX.centre[3 * g + 1], CX.centre[3 * g + 2]); }
      }
      for (let s = 0; s < CX.segCell.length; s++) {
        if (!globals.has(CX.segCell[s])) continue;
        for (let j = 0; j < 2; j++) { const p = CX.seg[2 * s + j]; seg.push(P[3 * p], P[3 * p + 1], P[3 * p + 2]); }
      }
      for (let s = 0; s < CX.dotCell.length; s++) if (globals.has(CX.dotCell[s])) { const p = CX.dot[s]; pts.push(P[3 * p], P[3 * p + 1], P[3 * p + 2]); }
      if (pts.length) out.push(drawable(gl.POINTS, { pos: Float32Array.from(pts) }, { colour, size: 12 }));
      if (seg.length) out.push(thickLines(Float32Array.from(seg), colour, 6));
      if (tri.length) { const d = drawable(gl.TRIANGLES, { pos: Float32Array.from(tri), ctr: Float32Array.from(ctr) }, { prog: progLit, colour }); d.offset = true; out.push(d); }
    }
    return out;
  }

  // ---------------------------------------------------------------- drawing
  function use(d, extra) {
    const pr = d.prog;
    gl.useProgram(pr.p);
    gl.uniformMatrix4fv(pr.u.uMvp, false, mvp);
    if (pr.u.uView) gl.uniformMatrix4fv(pr.u.uView, false, view);
    if (pr.u.uExplode) gl.uniform1f(pr.u.uExplode, d.hasCtr ? explode : 0);
    if (pr.u.uMid) gl.uniform3fv(pr.u.uMid, MID);
    if (pr.u.uSize) gl.uniform1f(pr.u.uSize, d.size * (window.devicePixelRatio || 1));
    if (pr.u.uWidth) gl.uniform1f(pr.u.uWidth, d.size * (window.devicePixelRatio || 1) * 0.5);
    if (pr.u.uViewport) gl.uniform2f(pr.u.uViewport, canvas.width / 2, canvas.height / 2);
    gl.uniform1f(pr.u.uFade, extra && extra.fade || 0);
    gl.uniform1f(pr.u.uAlpha, extra && extra.alpha !== undefined ? extra.alpha : 1);
    gl.bindVertexArray(d.vao);
    if (!d.hasCol) { gl.disableVertexAttribArray(2); gl.vertexAttrib4f(2, d.colour[0] / 255, d.colour[1] / 255, d.colour[2] / 255, 1); }
    if (!d.hasCtr) gl.vertexAttrib3f(1, MID[0], MID[1], MID[2]);
    if (d.offset) { gl.enable(gl.POLYGON_OFFSET_FILL); gl.polygonOffset(-1, -2); }
    if (d.indexed) gl.drawElements(d.mode, d.count, gl.UNSIGNED_INT, 0);
    else if (d.count) gl.drawArrays(d.mode, 0, d.count);
    gl.disable(gl.POLYGON_OFFSET_FILL);
    gl.bindVertexArray(null);
  }
  function drawCellsBase(fade) {
    if (!cellsView) return;
    if (isMap) {
      use(cellsView.faces, { fade });
      if (cellsView.outline && explode === 0) use(cellsView.outline, { fade: fade ? 0.6 : 0, alpha: 1 });
      if (!fade) for (const m of cellsView.marks || []) use(m);
    } else {
      for (const p of cellsView.parts) use(p.d, { fade: p.d.prog === progLit ? fade : Math.min(fade, 0.6) });
      use(cellsView.links, { fade: Math.min(fade, 0.6) });
    }
  }
  function overlays(list) {
    for (const d of list) use(d);
    gl.disable(gl.DEPTH_TEST);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    // the hidden parts, faintly: faces first, then lines and points over them
    for (const d of list) if (d.mode === gl.TRIANGLES && d.prog !== progThick) use(d, { alpha: 0.3 });
    for (const d of list) if (!(d.mode === gl.TRIANGLES && d.prog !== progThick)) use(d, { alpha: 0.5 });
    gl.disable(gl.BLEND);
    gl.enable(gl.DEPTH_TEST);
  }
  let firstFrame = null;
  function draw() {
    updateCamera();
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(BG[0], BG[1], BG[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    if (state.view === 'darts' && dartsView) {
      use(dartsView.darts);
      for (const c of dartsView.conns) use(c);
      use(dartsView.free);
    } else if (state.view === 'cells') {
      drawCellsBase(0);
    } else if (state.view === 'homology') {
      drawCellsBase(1);
      const list = [];
      genViews.forEach((g, k) => { if (state.gens[k]) list.push(...g); });
      overlays(list);
    }
    overlays(selectionView);
    if (firstFrame === null) firstFrame = performance.now();
  }
  let pending = false;
  function redraw() { if (!pending) { pending = true; requestAnimationFrame(() => { pending = false; draw(); }); } }

  function resize() {
    const r = window.devicePixelRatio || 1, cw = Math.max(canvas.clientWidth, 1), ch = Math.max(canvas.clientHeight, 1);
    canvas.width = Math.round(cw * Math.min(r, 2)); canvas.height = Math.round(ch * Math.min(r, 2));
  }

  function setView(v) {
    if (v === 'darts' && !isMap) v = 'cells';
    state.view = v;
    if (v === 'darts' && !dartsView) buildDarts();
    if (v !== 'darts' && !cellsView) { cellsView = isMap ? buildMapCells() : buildComplexCells(); colourCells(); }
    if (v === 'homology' && genViews.length !== meta.generators.length) {
      genViews = meta.generators.map((g, k) => cellOverlay(g.dim, new Set(g.cells), genColour(k)));
    }
    for (const b of document.querySelectorAll('#views button')) b.classList.toggle('on', b.dataset.view === v);
    $('legend-darts').style.display = v === 'darts' ? '' : 'none';
    $('legend-cells').style.display = v === 'cells' ? '' : 'none';
    $('legend-box').style.display = v === 'homology' ? 'none' : '';
    $('explode-row').style.display = v === 'darts' ? 'none' : '';
    $('colorby-row').style.display = v === 'cells' ? '' : 'none';
    $('gen-box').style.display = v === 'homology' ? '' : 'none';
    if (v === 'darts' && N > meta.dartLimit) buildMessageAgain(); else message('');
    if (selection.dim >= 0) highlight(selection.dim);
    redraw();
  }
  function buildMessageAgain() {
    const step = Math.ceil(N / meta.dartLimit);
    message(N.toLocaleString('en') + ' darts is above the darts view\'s limit of ' + meta.dartLimit.toLocaleString('en') + ': it shows the darts of one ' +
      (UNIT ? n + '-cell side (orbit <α0…α' + (n - 1) + '>)' : 'dart') + ' in ' + step + ' (' + kept.length.toLocaleString('en') + ' darts). The cells view shows everything.');
  }

  // generators list
  {
    const box = $('generators');
    if (!meta.generators.length) box.innerHTML = '<div class="small">none in this page (gmap view --generators)</div>';
    meta.generators.forEach((g, k) => {
      const row = document.createElement('div');
      row.className = 'gen-item';
      row.innerHTML = '<label><input type="checkbox" checked data-gen="' + k + '"><span class="swatch" style="background:' + css(genColour(k)) + '"></span></label>';
      row.querySelector('label').appendChild(document.createTextNode(g.name + ' — ' + g.cells.length + ' ' + g.dim + '-cell' + (g.cells.length === 1 ? '' : 's')));
      row.querySelector('input').addEventListener('change', (e) => { state.gens[k] = e.target.checked; redraw(); });
      box.appendChild(row);
    });
  }
  for (const b of document.querySelectorAll('#views button')) {
    if (b.dataset.view === 'darts' && !isMap) { b.disabled = true; b.title = 'a complex without darts'; }
    if (b.dataset.view === 'homology' && !meta.generators.length) b.title = 'no generators in this page';
    b.addEventListener('click', () => setView(b.dataset.view));
  }
  $('explode').addEventListener('input', (e) => { explode = e.target.value / 100 * 1.2; redraw(); });
  colorSel.addEventListener('change', () => { state.colorBy = colorSel.value || null; colourCells(); redraw(); });

  // ---------------------------------------------------------------- selection
  const selection = { dart: -1, cell: -1, dim: -1 };
  function project(x, y, z) {
    const m = mvp, cw = m[3] * x + m[7] * y + m[11] * z + m[15];
    return [(m[0] * x + m[4] * y + m[8] * z + m[12]) / cw, (m[1] * x + m[5] * y + m[9] * z + m[13]) / cw, (m[2] * x + m[6] * y + m[10] * z + m[14]) / cw, cw];
  }
  function anchor(d) {
    if (state.view === 'darts') return [0, 1, 2].map((a) => 0.5 * (DT[6 * d + a] + DT[6 * d + 3 + a]));
    const x = [0, 1, 2].map((a) => 0.7 * VP[3 * d + a] + 0.3 * MP[3 * d + a]);
    if (HF) { const h = 3 * HF.id[d], u = 3 * UNIT.id[d]; for (let a = 0; a < 3; a++) x[a] += 0.1 * (HFC[h + a] - x[a]) + explode * (UNITC[u + a] - MID[a]); }
    return x;
  }
  function pick(px, py) {
    updateCamera();
    const W = canvas.clientWidth, H = canvas.clientHeight;
    let best = -1, bestZ = Infinity, bestR = Infinity;
    const consider = (k, x) => {
      const p = project(x[0], x[1], x[2]);
      if (p[3] <= 0) return;
      const sx = (p[0] + 1) / 2 * W, sy = (1 - p[1]) / 2 * H, r = Math.hypot(sx - px, sy - py);
      if (r < 10 && (bestR >= 10 || p[2] < bestZ)) { best = k; bestZ = p[2]; bestR = r; } else if (bestR >= 10 && r < bestR) { best = k; bestR = r; bestZ = p[2]; }
    };
    if (isMap) {
      const list = state.view === 'darts' ? kept : null;
      if (list) for (const d of list) consider(d, anchor(d));
      else for (let d = 0; d < N; d++) consider(d, anchor(d));
    } else {
      for (let g = 0; g < CX.cellDim.length; g++) {
        const c = CX.centre, x = [c[3 * g], c[3 * g + 1], c[3 * g + 2]];
        if (CX.cellShown[g]) for (let a = 0; a < 3; a++) x[a] += explode * (x[a] - MID[a]);
        consider(g, x);
      }
    }
    return bestR < 30 ? best : -1;
  }
  function select(k) {
    selection.dart = -1; selection.cell = -1; selection.dim = -1;
    selectionView = [];
    const out = $('selection'), buttons = $('sel-buttons');
    buttons.innerHTML = '';
    if (k < 0) { out.textContent = 'click a dart (or a cell)'; redraw(); return; }
    if (isMap) {
      selection.dart = k;
      const lines = ['dart ' + k];
      const im = [];
      for (let i = 0; i <= n; i++) { const e = A[k * w + i]; im.push('α' + i + ' = ' + (e === k ? 'free' : e)); }
      lines.push(im.join(', '));
      for (let i = 0; i <= n; i++) {
        const c = cellsOf(i).id[k], t = labelText(i, c);
        lines.push(i + '-cell ' + c + (t ? ': ' + t : ''));
      }
      out.textContent = lines.join('\n');
      for (let i = 0; i <= n; i++) {
        const b = document.createElement('button');
        b.textContent = i + '-cell';
        b.addEventListener('click', () => highlight(i));
        buttons.appendChild(b);
      }
      selectionView = selectedDartView();
    } else {
      const dim = CX.cellDim[k], idx = CX.index[k], t = labelText(dim, idx);
      out.textContent = dim + '-cell ' + idx + (t ? '\n' + t : '');
      selectionView = cellOverlay(dim, new Set([idx]), rgb(SELECT_COLOUR));
    }
    redraw();
  }
  function selectedDartView() {
    const d = selection.dart;
    if (d < 0) return [];
    const x = state.view === 'darts' ? DT.slice(6 * d, 6 * d + 6) : Float32Array.from([...VP.subarray(3 * d, 3 * d + 3), ...MP.subarray(3 * d, 3 * d + 3)]);
    return [thickLines(x, [230, 0, 0], 5)];
  }
  function highlight(i) {
    if (selection.dart < 0 || i > n) return;
    selection.dim = i;
    const c = cellsOf(i).id[selection.dart];
    if (state.view === 'darts') {
      const ids = cellsOf(i).id, segs = [];
      for (const d of kept) if (ids[d] === c) segs.push(...DT.subarray(6 * d, 6 * d + 6));
      selectionView = [thickLines(Float32Array.from(segs), rgb(SELECT_COLOUR), 4), ...selectedDartView()];
    } else selectionView = [...cellOverlay(i, new Set([c]), rgb(SELECT_COLOUR)), ...selectedDartView()];
    $('selection').textContent = $('selection').textContent.split('\n(')[0] + '\n(highlighted: ' + i + '-cell ' + c + ')';
    redraw();
  }
  addEventListener('keydown', (e) => {
    if (e.key === 'Escape') select(-1);
    else if (/^[0-9]$/.test(e.key)) highlight(+e.key);
  });

  // ---------------------------------------------------------------- mouse
  let drag = null;
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());
  canvas.addEventListener('mousedown', (e) => { drag = { x: e.clientX, y: e.clientY, x0: e.clientX, y0: e.clientY, pan: e.button === 2 || e.shiftKey }; });
  addEventListener('mouseup', (e) => {
    if (drag && Math.hypot(e.clientX - drag.x0, e.clientY - drag.y0) < 4) {
      const r = canvas.getBoundingClientRect();
      select(pick(e.clientX - r.left, e.clientY - r.top));
    }
    drag = null;
  });
  addEventListener('mousemove', (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX; drag.y = e.clientY;
    if (drag.pan) {
      const s = cam.dist * 0.0015;
      for (let a = 0; a < 3; a++) cam.target[a] += -dx * s * cam.right[a] + dy * s * cam.up[a];
    } else {
      cam.yaw -= dx * 0.008;
      cam.pitch = Math.max(-1.55, Math.min(1.55, cam.pitch + dy * 0.008));
    }
    redraw();
  });
  canvas.addEventListener('wheel', (e) => { e.preventDefault(); cam.dist *= Math.exp(e.deltaY * 0.001); redraw(); }, { passive: false });
  addEventListener('resize', () => { resize(); redraw(); });

  // ---------------------------------------------------------------- start
  // the address may choose the view and the camera: #view=cells&explode=30&yaw=-0.9&pitch=0.4&zoom=1.2
  const hash = new Map(location.hash.slice(1).split('&').map((kv) => kv.split('=')));
  let first = ['darts', 'cells', 'homology'].includes(hash.get('view')) ? hash.get('view') : meta.view;
  if (hash.has('explode')) { const x = +hash.get('explode'); if (x >= 0 && x <= 100) { $('explode').value = x; explode = x / 100 * 1.2; } }
  if (isFinite(+hash.get('yaw')) && hash.has('yaw')) cam.yaw = +hash.get('yaw');
  if (isFinite(+hash.get('pitch')) && hash.has('pitch')) cam.pitch = Math.max(-1.55, Math.min(1.55, +hash.get('pitch')));
  if (+hash.get('zoom') > 0) cam.dist /= +hash.get('zoom');
  resize();
  state.colorBy = meta.colorBy;
  colorSel.value = meta.colorBy || '';
  state.view = first;
  setView(first);
  mark('built');
  draw();
  mark('drawn');

  // ---------------------------------------------------------------- self test (#selftest)
  function pixels() {
    const W = canvas.width, H = canvas.height, px = new Uint8Array(W * H * 4);
    gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, px);
    return px;
  }
  function nonBlank(px) {
    const bg = BG.map((c) => Math.round(c * 255));
    let k = 0;
    for (let i = 0; i < px.length; i += 4) if (Math.abs(px[i] - bg[0]) + Math.abs(px[i + 1] - bg[1]) + Math.abs(px[i + 2] - bg[2]) > 12) k++;
    return k;
  }
  function changed(a, b) { let k = 0; for (let i = 0; i < a.length; i += 4) if (a[i] !== b[i] || a[i + 1] !== b[i + 1] || a[i + 2] !== b[i + 2]) k++; return k; }
  window.gmapViewer = { meta, setView, draw, select, highlight, pixels, state, firstFrameMs: () => firstFrame - T0 };
  if (location.hash.indexOf('selftest') >= 0) {
    const r = { firstFrameMs: firstFrame, setupMs: firstFrame - T0, marks, scriptStart: T0, canvas: [canvas.width, canvas.height], views: {}, darts: N, dim: n };
    const first = state.view;
    for (const v of isMap ? ['darts', 'cells', 'homology'] : ['cells', 'homology']) {
      const t = performance.now();
      setView(v); draw();
      r.views[v] = { nonBlank: nonBlank(pixels()), ms: performance.now() - t };
      if (v === 'darts') r.message = $('message').textContent;
    }
    r.thinned = isMap && N > meta.dartLimit ? kept.length : null;
    setView('cells'); draw();
    r.legendCells = [...document.querySelectorAll('#legend-cells .legend-item')].map((e) => e.textContent);
    r.legendDarts = [...document.querySelectorAll('#legend-darts .legend-item')].map((e) => e.textContent);
    setView('homology'); draw();
    const all = pixels();
    r.generatorToggle = meta.generators.map((g, k) => {
      state.gens[k] = false; draw();
      const c = changed(all, pixels());
      state.gens[k] = true;
      return c;
    });
    draw();
    if (isMap && N > 0) {
      setView('cells'); draw();
      const before = pixels();
      select(0); highlight(Math.min(2, n)); draw();
      r.selection = $('selection').textContent;
      r.highlightChanged = changed(before, pixels());
      select(-1);
    }
    if (isMap && N <= meta.dartLimit) {
      // the cells as the page numbers them: their counts, and numbered in the order of their
      // smallest darts (as DenseMap::cells)
      r.cellCounts = [];
      r.numberedBySmallestDart = true;
      for (let i = 0; i <= n; i++) {
        const o = cellsOf(i);
        r.cellCounts.push(o.count);
        let next = 0;
        for (let d = 0; d < N; d++) { if (o.id[d] === next) next++; else if (o.id[d] > next) r.numberedBySmallestDart = false; }
      }
    }
    r.resources = performance.getEntriesByType('resource').map((e) => e.name);
    r.domUrls = [...document.querySelectorAll('[src],[href]')].map((e) => e.getAttribute('src') || e.getAttribute('href'));
    r.errors = window.gmapErrors.slice();
    r.totalMs = performance.now();
    setView(first); draw();
    selftestOut.textContent = JSON.stringify(r);
    // for browsers whose headless mode prints the console but cannot dump the document (Firefox)
    console.log('gmap-selftest ' + selftestOut.textContent);
  }
})();
