// The viewer page of `ccdlab view` (docs/viewer.md). Reads the data `ccdlab view` embedded
// (experiments/view_data.hpp, format ccdlab-view/1) and draws it with three.js.
//
// Motion: each body's centre is given as the pieces of its exact trajectory
// [t0, t1, p, v, a] (p + v s + a s^2 / 2, s = t - t0; a later piece wins at a break), and
// each spinning shape's orientation as rotation pieces [t0, t1, q0 (w x y z), omega]
// (q(t) = exp(s omega / 2) q0). The page only evaluates them: no physics of its own.
//
// Bounds: the volumes each run's bound tested (`volumes` of each run, computed by the C++
// bounds: experiments/view_volumes.hpp): per body, windows [w0, w1, volumes] with boxes,
// spheres, capsules and oriented boxes. The page draws those of the window that holds t and
// computes no bound of its own; where the page holds none (a large page keeps only the
// windows of the missed contacts) it says so.
(function () {
  'use strict';

  const PIECE = 11;     // numbers per centre piece
  const ROT = 9;        // numbers per rotation piece
  const HIGHLIGHT = 0xff0000;
  const HIGHLIGHT_SECOND = 0xd00000;
  const SCENERY = 0x9c8f6a;  // static scenery (floors, ramps, meshes): opaque, unlit
  const el = (id) => document.getElementById(id);
  const data = JSON.parse(el('ccdlab-data').textContent);
  const body = document.body;

  const state = {
    t: 0, playing: false, speed: 1, run: null, pair: null, polygon: null, missedIndex: -1, dirty: true,
    fragmentReady: false,
  };

  // ---------------------------------------------------------------- the URL fragment
  function readFragment() {
    const out = {};
    const text = window.location.hash.replace(/^#/, '');
    for (const part of text.split('&')) {
      if (!part) continue;
      const eq = part.indexOf('=');
      const key = decodeURIComponent(eq < 0 ? part : part.slice(0, eq));
      out[key] = eq < 0 ? '' : decodeURIComponent(part.slice(eq + 1));
    }
    return out;
  }

  function writeFragment() {
    if (!state.fragmentReady) return;
    const parts = [];
    if (state.run) {
      parts.push('method=' + encodeURIComponent(state.run.method).replace(/%2F/g, '/').replace(/%3A/g, ':').replace(/%40/g, '@'));
      parts.push('dt=' + formatNumber(state.run.dt));
    }
    parts.push('t=' + formatNumber(state.t));
    if (state.pair && state.pair.length === 2) parts.push('pair=' + state.pair[0] + '-' + state.pair[1]);
    try {
      window.history.replaceState(null, '', '#' + parts.join('&'));
    } catch (e) { /* some browsers refuse replaceState on file:// URLs: the view still works */ }
  }

  function formatNumber(x) {
    return String(Number(x.toPrecision(9)));
  }

  // ---------------------------------------------------------------- motion
  // Index of the piece of flat array `arr` (stride `stride`) that holds t (the later one at a break).
  function pieceIndex(arr, stride, t, guess) {
    const m = arr.length / stride;
    if (guess >= 0 && guess < m && arr[guess * stride] <= t && (t < arr[guess * stride + 1] || guess === m - 1))
      return guess;
    let lo = 0, hi = m - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (arr[mid * stride] <= t) lo = mid; else hi = mid - 1;
    }
    return lo;
  }

  function BodyMotion(bodies) {
    const n = bodies.count;
    const cursor = new Int32Array(n);
    const rcursor = new Int32Array(n);
    const rotations = bodies.rotations || [];
    this.count = n;
    this.radius = bodies.radius;
    this.shape = bodies.shape;
    this.pieces = bodies.pieces;
    // Centre of body i at t into out (a THREE.Vector3).
    this.position = function (i, t, out) {
      const arr = bodies.pieces[i];
      const k = pieceIndex(arr, PIECE, t, cursor[i]);
      cursor[i] = k;
      const o = k * PIECE, s = t - arr[o];
      const h = 0.5 * s * s;
      return out.set(arr[o + 2] + arr[o + 5] * s + arr[o + 8] * h,
                     arr[o + 3] + arr[o + 6] * s + arr[o + 9] * h,
                     arr[o + 4] + arr[o + 7] * s + arr[o + 10] * h);
    };
    this.velocity = function (i, t, out) {
      const arr = bodies.pieces[i];
      const k = pieceIndex(arr, PIECE, t, cursor[i]);
      const o = k * PIECE, s = t - arr[o];
      return out.set(arr[o + 5] + arr[o + 8] * s, arr[o + 6] + arr[o + 9] * s, arr[o + 7] + arr[o + 10] * s);
    };
    const axis = new THREE.Vector3(), dq = new THREE.Quaternion(), q0 = new THREE.Quaternion();
    // Orientation of body i at t into out (a THREE.Quaternion); identity without rotations.
    this.orientation = function (i, t, out) {
      if (!rotations.length) return out.set(0, 0, 0, 1);
      const arr = rotations[i];
      const k = pieceIndex(arr, ROT, t, rcursor[i]);
      rcursor[i] = k;
      const o = k * ROT, s = t - arr[o];
      q0.set(arr[o + 3], arr[o + 4], arr[o + 5], arr[o + 2]);
      axis.set(arr[o + 6], arr[o + 7], arr[o + 8]);
      const w = axis.length();
      if (w === 0) return out.copy(q0);
      axis.multiplyScalar(1 / w);
      dq.setFromAxisAngle(axis, w * s);
      return out.multiplyQuaternions(dq, q0).normalize();
    };
  }

  // ---------------------------------------------------------------- bounds of a method
  // The step [t0, t1] of a fixed-step `run` that holds t: samples at k dt (k dt <= horizon),
  // a step from each sample to the next or to the horizon (experiments/runner.cpp).
  function stepAt(run, t) {
    const T = data.horizon;
    let k = Math.max(0, Math.floor(t / run.dt + 1e-9));
    while (k > 0 && k * run.dt >= T) --k;
    return { k: k, t0: k * run.dt, t1: Math.min((k + 1) * run.dt, T) };
  }

  // The entry [w0, w1, volumes] of body i in `run` whose window holds t (the later one at a
  // shared end), or null where the page holds none.
  function volumeEntry(run, i, t) {
    const v = run.volumes;
    const list = v && v.bodies && v.bodies[i];
    if (!list || !list.length) return null;
    let lo = 0, hi = list.length - 1, best = -1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (list[mid][0] <= t) { best = mid; lo = mid + 1; } else hi = mid - 1;
    }
    return best >= 0 && t <= list[best][1] ? list[best] : null;
  }

  // Why a run has no volumes at some place (the C++ side's reason), for the pair's line.
  function volumesNote(run) {
    const v = run.volumes;
    if (!v) return 'the page holds no bounds for this run';
    return v.coverage === 'all' ? '' : v.reason;
  }

  // ---------------------------------------------------------------- the side panel
  const runs = data.runs || [];
  const methods = [];
  for (const r of runs) if (methods.indexOf(r.method) < 0) methods.push(r.method);

  // A run's missed contacts, body-body ({a, b}) and body-scenery ({a: body, polygon}), in
  // order of entry; null when the results list none (run without --list-missed).
  function missedOf(run) {
    if (!run || (run.missed_events === undefined && run.static_missed_events === undefined)) return null;
    if (!run.missedList) {
      const list = (run.missed_events || []).map((m) => ({ a: m.a, b: m.b, polygon: null, enter: m.enter, exit: m.exit }));
      for (const m of run.static_missed_events || [])
        list.push({ a: m.body, b: null, polygon: m.polygon, enter: m.enter, exit: m.exit });
      list.sort((x, y) => x.enter - y.enter);  // stable: each kind keeps its order
      run.missedList = list;
    }
    return run.missedList;
  }

  // Missed contacts of a run, body-body and body-scenery together.
  function missedCount(run) { return (run.missed || 0) + (run.static_missed || 0); }

  function runsOf(method) {
    return runs.filter((r) => r.method === method).sort((a, b) => a.dt - b.dt);
  }

  function fillRunControls() {
    const ms = el('method'), ds = el('dt');
    ms.innerHTML = '';
    for (const m of methods) ms.add(new Option(m, m));
    ms.disabled = ds.disabled = methods.length === 0;
    if (!methods.length) {
      el('run-info').textContent = data.kind === 'cloth' ? 'cloth frames: no method runs'
        : 'no results given (ccdlab view --results RESULTS.json)';
    }
    ms.addEventListener('change', () => selectRun(ms.value, state.run ? state.run.dt : null, true));
    ds.addEventListener('change', () => selectRun(ms.value, Number(ds.value), true));
  }

  // Chooses the run of `method` whose dt is nearest `dt` (relative tolerance 1e-9 for a match).
  function selectRun(method, dt, byUser) {
    const list = runsOf(method);
    if (!list.length) return;
    let best = list[list.length - 1];
    if (dt !== null && dt !== undefined && isFinite(dt)) {
      let err = Infinity;
      for (const r of list) {
        const e = Math.abs(r.dt - dt) / Math.max(r.dt, dt);
        if (e < err) { err = e; best = r; }
      }
    } else {
      // By default the largest dt with a miss (the interesting one), else the largest dt.
      const missing = list.filter((r) => missedCount(r) > 0);
      if (missing.length) best = missing[missing.length - 1];
    }
    state.run = best;
    el('method').value = method;
    const ds = el('dt');
    ds.innerHTML = '';
    for (const r of list) ds.add(new Option((r.hz ? r.dt.toPrecision(6) + ' s (' + Number(r.hz.toPrecision(6)) + ' Hz)' : r.dt.toPrecision(6) + ' s'), String(r.dt)));
    ds.value = String(best.dt);
    const r = best;
    // Contacts to detect: the events less those in progress at t = 0 and the undecided ones.
    const body = (r.events || 0) - (r.initial_contacts || 0) - (r.undecided || 0);
    const scenery = (r.static_events || 0) - (r.static_initial_contacts || 0) - (r.static_undecided || 0);
    const kinds = r.static_events ? ' (' + (r.missed || 0) + ' of ' + body + ' body-body, ' + (r.static_missed || 0) +
      ' of ' + scenery + ' body-scenery)' : '';
    el('run-info').textContent = r.method + ' at dt = ' + formatNumber(r.dt) + ' s: ' +
      (r.continuous ? 'continuous' : 'discrete') + (r.conservative ? ', conservative' : '') + '; ' +
      (r.missed !== undefined ? missedCount(r) + ' missed of ' + (body + scenery) + ' contacts' + kinds : '') +
      (r.false_positives !== undefined ? ', ' + r.false_positives + ' false positives' : '') +
      (missedOf(r) === null && missedCount(r) > 0 ? ' (the results list no missed contacts: run with --list-missed)' : '') +
      (volumesNote(r) ? '. Bounds: ' + volumesNote(r) : '');
    fillMissedTable(r);
    if (byUser) { state.pair = null; state.missedIndex = -1; }
    state.dirty = true;
    drawTimeline();
    writeFragment();
  }

  function fillMissedTable(run) {
    const tbody = el('missed').tBodies[0];
    tbody.innerHTML = '';
    const list = missedOf(run) || [];
    el('missed-count').textContent = '(' + list.length + ')';
    list.forEach((m, index) => {
      const tr = document.createElement('tr');
      tr.setAttribute('data-missed', '');
      tr.dataset.a = m.a;
      if (m.polygon === null) tr.dataset.b = m.b; else tr.dataset.polygon = m.polygon;
      tr.dataset.enter = m.enter;
      tr.dataset.exit = m.exit;
      tr.dataset.index = index;
      for (const x of [m.a, m.polygon === null ? m.b : 'scenery ' + m.polygon, m.enter.toPrecision(7), m.exit.toPrecision(7)]) {
        const td = document.createElement('td');
        td.textContent = x;
        tr.appendChild(td);
      }
      tr.addEventListener('click', () => jumpToMissed(index));
      tbody.appendChild(tr);
    });
  }

  function jumpToMissed(index) {
    const list = missedOf(state.run) || [];
    if (!list.length) return;
    index = ((index % list.length) + list.length) % list.length;
    const m = list[index];
    state.missedIndex = index;
    state.playing = false;
    state.polygon = m.polygon;
    setPair(m.polygon === null ? [m.a, m.b] : [m.a], true);
    setTime(0.5 * (m.enter + m.exit));
  }

  function markSelectedRow() {
    for (const tr of el('missed').tBodies[0].rows) {
      const on = state.pair && Number(tr.dataset.a) === state.pair[0] && Number(tr.dataset.index) === state.missedIndex &&
        (state.pair.length === 1 ? Number(tr.dataset.polygon) === state.polygon : Number(tr.dataset.b) === state.pair[1]);
      tr.classList.toggle('selected', !!on);
      if (on) {  // scroll the table only, not the page
        const wrap = el('missed-wrap');
        if (tr.offsetTop < wrap.scrollTop + 24 || tr.offsetTop > wrap.scrollTop + wrap.clientHeight - 24)
          wrap.scrollTop = Math.max(0, tr.offsetTop - wrap.clientHeight / 2);
      }
    }
  }

  // The timeline strip over the slider: sample instants (grey) and missed contacts (red).
  function drawTimeline() {
    const c = el('timeline');
    const w = c.clientWidth || 600;
    c.width = w;
    const g = c.getContext('2d');
    g.clearRect(0, 0, w, c.height);
    const T = data.horizon;
    if (state.run && T / state.run.dt <= w / 2) {
      g.fillStyle = '#999';
      for (let t = 0; t <= T + 1e-12; t += state.run.dt) g.fillRect(Math.round(t / T * (w - 1)), 8, 1, 6);
    }
    if (missedOf(state.run)) {
      g.fillStyle = '#d00';
      for (const m of missedOf(state.run)) {
        const x0 = m.enter / T * (w - 1), x1 = m.exit / T * (w - 1);
        g.fillRect(Math.floor(x0), 0, Math.max(2, x1 - x0), 7);
      }
    }
    g.fillStyle = '#000';
    g.fillRect(Math.round(state.t / T * (w - 1)), 0, 1, 14);
  }

  // ---------------------------------------------------------------- time
  function setTime(t) {
    state.t = Math.min(Math.max(t, 0), data.horizon);
    el('time').value = String(Math.round(state.t / data.horizon * 100000));
    state.dirty = true;
    writeFragment();
  }

  function setupTimeControls() {
    el('time').addEventListener('input', () => { state.playing = false; setTime(Number(el('time').value) / 100000 * data.horizon); });
    el('play').addEventListener('click', togglePlay);
    el('speed').addEventListener('change', () => { state.speed = Number(el('speed').value); });
    const step = (dir) => {
      state.playing = false;
      const h = state.run ? state.run.dt : data.horizon / 1000;
      setTime((Math.round(state.t / h + 1e-9) + dir) * h);
    };
    el('step-back').addEventListener('click', () => step(-1));
    el('step-fwd').addEventListener('click', () => step(1));
    window.addEventListener('keydown', (e) => {
      if (e.target && (e.target.tagName === 'SELECT' || e.target.tagName === 'INPUT' && e.target.type !== 'range')) return;
      if (e.key === ' ') { togglePlay(); e.preventDefault(); }
      else if (e.key === 'ArrowLeft') { step(-1); e.preventDefault(); }
      else if (e.key === 'ArrowRight') { step(1); e.preventDefault(); }
      else if (e.key === 'n') jumpToMissed(state.missedIndex + 1);
      else if (e.key === 'p') jumpToMissed(state.missedIndex - 1);
      else if (e.key === 'Escape') setPair(null, false);
    });
  }

  function togglePlay() {
    if (!state.playing && state.t >= data.horizon) setTime(0);
    state.playing = !state.playing;
    lastFrame = null;
  }

  function setPair(pair, focus) {
    state.pair = pair;
    state.focusPair = !!(pair && focus);
    markSelectedRow();
    state.dirty = true;
    writeFragment();
  }

  // ---------------------------------------------------------------- 3D
  let renderer = null, scene3 = null, camera = null, controls = null, lastFrame = null;
  const layers = {};
  let motion = null;
  let updateScene = function () {};

  function make3D() {
    const canvas = el('canvas');
    renderer = new THREE.WebGLRenderer({ canvas: canvas, antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xf4f4f1);
    scene3 = new THREE.Scene();
    camera = new THREE.PerspectiveCamera(40, 1, 1e-3, 1e7);
    scene3.add(new THREE.HemisphereLight(0xffffff, 0x667788, 0.9));
    const sun = new THREE.DirectionalLight(0xffffff, 0.6);
    sun.position.set(0.4, 1, 0.6);
    scene3.add(sun);
    controls = new THREE.OrbitControls(camera, canvas);
    controls.addEventListener('change', () => { state.dirty = true; });
    resize();
    window.addEventListener('resize', () => { resize(); drawTimeline(); state.dirty = true; });
  }

  function resize() {
    const canvas = el('canvas');
    const w = canvas.parentElement.clientWidth || 800, h = canvas.parentElement.clientHeight || 600;
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
  }

  function frameView(min, max) {
    const centre = min.clone().add(max).multiplyScalar(0.5);
    const size = Math.max(max.clone().sub(min).length(), 1e-6);
    controls.target.copy(centre);
    camera.position.copy(centre).add(new THREE.Vector3(0.55, 0.45, 1).normalize().multiplyScalar(size * 1.35));
    camera.near = size * 1e-4;
    camera.far = size * 100;
    camera.updateProjectionMatrix();
    controls.update();
  }

  function addWalls(box) {
    const min = new THREE.Vector3().fromArray(box.min), max = new THREE.Vector3().fromArray(box.max);
    const geo = new THREE.EdgesGeometry(new THREE.BoxBufferGeometry(max.x - min.x, max.y - min.y, max.z - min.z));
    const lines = new THREE.LineSegments(geo, new THREE.LineBasicMaterial({ color: 0x888888 }));
    lines.position.copy(min).add(max).multiplyScalar(0.5);
    scene3.add(lines);
    layers.walls = lines;
  }

  // Triangle fans of the polygons (flat vertex arrays) as one geometry.
  function polygonGeometry(polygons) {
    const coords = [];
    for (const f of polygons)
      for (let k = 1; k + 1 < f.length / 3; ++k)
        for (const v of [0, k, k + 1]) coords.push(f[3 * v], f[3 * v + 1], f[3 * v + 2]);
    const geo = new THREE.BufferGeometry();
    geo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(coords), 3));
    return geo;
  }

  // The static scenery, opaque with dark edges; returns each polygon's plane {n, d}
  // (n . x = d, n from Newell's formula) for the truth's body-scenery contacts.
  function addScenery(polygons) {
    const planes = polygons.map((f) => {
      const n = new THREE.Vector3(), c = new THREE.Vector3();
      const m = f.length / 3;
      for (let k = 0; k < m; ++k) {
        const a = 3 * k, b = 3 * ((k + 1) % m);
        n.x += (f[a + 1] - f[b + 1]) * (f[a + 2] + f[b + 2]);
        n.y += (f[a + 2] - f[b + 2]) * (f[a] + f[b]);
        n.z += (f[a] - f[b]) * (f[a + 1] + f[b + 1]);
        c.x += f[a] / m; c.y += f[a + 1] / m; c.z += f[a + 2] / m;
      }
      n.normalize();
      return { n: n, d: n.dot(c) };
    });
    if (!polygons.length) return planes;
    const group = new THREE.Group();
    const geo = polygonGeometry(polygons);
    const mesh = new THREE.Mesh(geo, new THREE.MeshBasicMaterial({ color: SCENERY, side: THREE.DoubleSide,
      polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
    group.add(mesh);
    const edges = [];
    for (const f of polygons) {
      const m = f.length / 3;
      for (let k = 0; k < m; ++k)
        for (const v of [k, (k + 1) % m]) edges.push(f[3 * v], f[3 * v + 1], f[3 * v + 2]);
    }
    const edgeGeo = new THREE.BufferGeometry();
    edgeGeo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(edges), 3));
    group.add(new THREE.LineSegments(edgeGeo, new THREE.LineBasicMaterial({ color: 0x5a5035 })));
    scene3.add(group);
    layers.scenery = group;
    return planes;
  }

  // A growable set of instanced meshes of one geometry (translucent bounds, ghosts).
  function InstancePool(geometry, material, capacity) {
    this.geometry = geometry;
    this.material = material;
    this.mesh = null;
    this.count = 0;
    this.capacity = 0;
    this.matrices = [];
    this.ensure = function (n) {
      if (n <= this.capacity) return;
      const old = this.mesh;
      if (old) scene3.remove(old);
      this.capacity = Math.max(n, capacity, this.capacity * 2);
      this.mesh = new THREE.InstancedMesh(this.geometry, this.material, this.capacity);
      if (old) this.mesh.instanceMatrix.array.set(old.instanceMatrix.array);  // the instances pushed so far
      this.mesh.frustumCulled = false;
      this.mesh.renderOrder = material.transparent ? 2 : 0;
      scene3.add(this.mesh);
    };
    this.begin = function () { this.count = 0; };
    const m = new THREE.Matrix4();
    this.push = function (position, quaternion, scale) {
      this.ensure(this.count + 1);
      m.compose(position, quaternion, scale);
      this.mesh.setMatrixAt(this.count++, m);
    };
    this.end = function (visible) {
      if (!this.mesh) return;
      this.mesh.count = this.count;
      this.mesh.visible = visible && this.count > 0;
      this.mesh.instanceMatrix.needsUpdate = true;
    };
  }

  // Many spheres: one point per body, drawn as a shaded disc of the sphere's projected size
  // (an impostor: one vertex per body instead of a mesh's hundred). Above this count, unless
  // the fragment says spheres=mesh; spheres=points forces it.
  const POINTS_ABOVE = 2000;
  function usePoints(count) {
    const f = readFragment().spheres;
    return f === 'points' || (f !== 'mesh' && count > POINTS_ABOVE);
  }

  function spherePoints(radii) {
    const geo = new THREE.BufferGeometry();
    geo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * radii.length), 3));
    geo.setAttribute('radius', new THREE.BufferAttribute(new Float32Array(radii), 1));
    const material = new THREE.ShaderMaterial({
      uniforms: { scale: { value: 1 }, colour: { value: new THREE.Color(0x6d8fb3) } },
      vertexShader: [
        'attribute float radius;', 'uniform float scale;',
        'void main() {',
        '  vec4 mv = modelViewMatrix * vec4(position, 1.0);',
        '  gl_Position = projectionMatrix * mv;',
        '  gl_PointSize = max(2.0, 2.0 * radius * scale / max(-mv.z, 1e-6));',
        '}'].join('\n'),
      fragmentShader: [
        'uniform vec3 colour;',
        'void main() {',
        '  vec2 q = 2.0 * gl_PointCoord - 1.0;',
        '  float d = dot(q, q);',
        '  if (d > 1.0) discard;',
        '  vec3 n = vec3(q.x, -q.y, sqrt(1.0 - d));',
        '  float light = 0.45 + 0.55 * max(0.0, dot(n, normalize(vec3(0.4, 0.6, 0.7))));',
        '  gl_FragColor = vec4(colour * light + 0.08, 1.0);',
        '}'].join('\n'),
    });
    const points = new THREE.Points(geo, material);
    points.frustumCulled = false;
    return points;
  }

  function capsuleGeometry(halfLength, radius, segments) {
    // A capsule along x: a lathe of two quarter circles joined by a straight side.
    const pts = [];
    const k = Math.max(4, segments >> 1);
    for (let i = 0; i <= k; ++i) {
      const a = -Math.PI / 2 + (Math.PI / 2) * i / k;
      pts.push(new THREE.Vector2(radius * Math.cos(a), -halfLength + radius * Math.sin(a)));
    }
    for (let i = 0; i <= k; ++i) {
      const a = (Math.PI / 2) * i / k;
      pts.push(new THREE.Vector2(radius * Math.cos(a), halfLength + radius * Math.sin(a)));
    }
    const g = new THREE.LatheBufferGeometry(pts, segments);
    g.rotateZ(-Math.PI / 2);
    return g;
  }

  function shapeGeometry(shape, segments) {
    if (shape.kind === 'capsule') return capsuleGeometry(shape.half_length, shape.radius, segments);
    if (shape.kind === 'box') {
      const h = shape.half_extents;
      return new THREE.BoxBufferGeometry(2 * h[0], 2 * h[1], 2 * h[2]);
    }
    if (shape.kind === 'hull') return new THREE.ConvexBufferGeometry(shape.points.map((p) => new THREE.Vector3().fromArray(p)));
    return new THREE.SphereBufferGeometry(shape.radius, segments, segments >> 1);
  }

  function makeBodies3D() {
    motion = new BodyMotion(data.bodies);
    const n = motion.count;
    const segments = n > 5000 ? 8 : n > 2000 ? 10 : n > 200 ? 16 : 24;
    const unitSphere = new THREE.SphereBufferGeometry(1, segments, Math.max(6, segments >> 1));
    const bodyMaterial = new THREE.MeshLambertMaterial({ color: 0x6d8fb3 });
    const shapes = data.shapes || [];
    // One instanced mesh per shape; plain spheres (and sphere shapes) share the unit sphere.
    const groupOf = new Int32Array(n);
    const groups = [{ geometry: unitSphere, scaled: true, members: [] }];
    const shapeGroup = shapes.map((s) => {
      if (s.kind === 'sphere') return 0;
      groups.push({ geometry: shapeGeometry(s, segments), scaled: false, members: [] });
      return groups.length - 1;
    });
    for (let i = 0; i < n; ++i) {
      const s = motion.shape[i];
      groupOf[i] = s < 0 ? 0 : shapeGroup[s];
      groups[groupOf[i]].members.push(i);
    }
    for (const g of groups) {
      if (!g.members.length) continue;
      if (g === groups[0] && usePoints(g.members.length)) {
        g.points = spherePoints(g.members.map((i) => motion.radius[i]));
        scene3.add(g.points);
        continue;
      }
      g.mesh = new THREE.InstancedMesh(g.geometry, bodyMaterial, g.members.length);
      g.mesh.frustumCulled = false;
      scene3.add(g.mesh);
    }
    // The highlighted pair: drawn in red over everything else.
    // Two shades of red, so that two overlapping bodies stay apart.
    // Marked transparent (fully opaque) so that they are drawn after the translucent bounds.
    const hiMaterials = [HIGHLIGHT, HIGHLIGHT_SECOND].map((c) =>
      new THREE.MeshBasicMaterial({ color: c, depthTest: false, transparent: true, opacity: 1 }));
    const hiGhost = new THREE.MeshBasicMaterial({ color: HIGHLIGHT, wireframe: true, transparent: true, opacity: 0.5 });
    const highlight = [0, 1].map((k) => {
      const m = new THREE.Mesh(unitSphere, hiMaterials[k]);
      m.renderOrder = 10;
      m.visible = false;
      scene3.add(m);
      return m;
    });
    const ghosts = [0, 1].map(() => {
      const m = new THREE.Mesh(unitSphere, hiGhost);
      m.visible = false;
      scene3.add(m);
      return m;
    });
    // The pair's paths over their windows, drawn over everything: a tunnelling body's
    // path crosses the other body between two samples.
    const PATH_POINTS = 64;
    const pathGeo = new THREE.BufferGeometry();
    pathGeo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * 2 * 2 * PATH_POINTS), 3));
    const pathLines = new THREE.LineSegments(pathGeo, new THREE.LineBasicMaterial({ color: 0x900000, depthTest: false }));
    pathLines.renderOrder = 11;
    pathLines.frustumCulled = false;
    pathLines.visible = false;
    scene3.add(pathLines);
    // Bounds: boxes, spheres and capsules (a cylinder and two spheres), translucent.
    const boundMaterial = new THREE.MeshBasicMaterial({ color: 0xe8a020, transparent: true, opacity: 0.25, depthWrite: false });
    const pairBoundMaterial = new THREE.MeshBasicMaterial({ color: 0xd03030, transparent: true, opacity: 0.3, depthWrite: false, depthTest: false });
    const boxGeo = new THREE.BoxBufferGeometry(1, 1, 1);
    const cylGeo = new THREE.CylinderBufferGeometry(1, 1, 1, 16, 1, true);
    const pools = {
      box: new InstancePool(boxGeo, boundMaterial, 64), sphere: new InstancePool(unitSphere, boundMaterial, 64),
      cyl: new InstancePool(cylGeo, boundMaterial, 64),
      pairBox: new InstancePool(boxGeo, pairBoundMaterial, 16), pairSphere: new InstancePool(unitSphere, pairBoundMaterial, 16),
      pairCyl: new InstancePool(cylGeo, pairBoundMaterial, 16),
    };
    // The truth's contacts at t: a line between the centres (body-body), from the centre to
    // the polygon's plane (body-scenery).
    const truth = data.truth || [];
    const staticTruth = data.static_truth || [];
    const plane = addScenery(data.scenery || []);
    const hiPolygonMaterial = new THREE.MeshBasicMaterial({ color: HIGHLIGHT, side: THREE.DoubleSide, depthTest: false,
      transparent: true, opacity: 0.6 });
    let hiPolygon = null, hiPolygonIndex = null;
    // The highlighted scenery polygon (a missed body-scenery contact), or none.
    function sceneryHighlight(j) {
      if (j === hiPolygonIndex) return;
      if (hiPolygon) { scene3.remove(hiPolygon); hiPolygon.geometry.dispose(); hiPolygon = null; }
      hiPolygonIndex = j;
      if (j === null || !data.scenery[j]) return;
      hiPolygon = new THREE.Mesh(polygonGeometry([data.scenery[j]]), hiPolygonMaterial);
      hiPolygon.renderOrder = 9;
      scene3.add(hiPolygon);
    }
    const contactGeo = new THREE.BufferGeometry();
    let contactCapacity = 0;
    const contactLines = new THREE.LineSegments(contactGeo, new THREE.LineBasicMaterial({ color: 0x109030 }));
    contactLines.frustumCulled = false;
    scene3.add(contactLines);

    const pos = new THREE.Vector3(), quat = new THREE.Quaternion(), scale = new THREE.Vector3();
    const one = new THREE.Vector3(1, 1, 1), ident = new THREE.Quaternion();
    const m4 = new THREE.Matrix4();
    const centres = new Float32Array(3 * n);
    const up = new THREE.Vector3(0, 1, 0);

    // Draws volume `v` of the page's data (experiments/view_volumes.hpp) with the pools
    // `box`, `sphere` and `cyl`, and merges the world box of what it drew into `hull`
    // ({lo, hi}, from the instance transforms themselves: what tests read back).
    const axisX = new THREE.Vector3(), axisY = new THREE.Vector3(), axisZ = new THREE.Vector3();
    const e = new THREE.Vector3(), basis = new THREE.Matrix4();
    function mergeBall(hull, c, r) {
      for (let k = 0; k < 3; ++k) {
        hull.lo[k] = Math.min(hull.lo[k], c.getComponent(k) - r);
        hull.hi[k] = Math.max(hull.hi[k], c.getComponent(k) + r);
      }
    }
    function pushBox(pool, centre, q, size, hull) {
      pool.push(centre, q, size);
      m4.compose(centre, q, size);
      const el4 = m4.elements;  // column-major: the unit cube's half-extents are half the columns
      for (let k = 0; k < 3; ++k) {
        const half = 0.5 * (Math.abs(el4[k]) + Math.abs(el4[4 + k]) + Math.abs(el4[8 + k]));
        hull.lo[k] = Math.min(hull.lo[k], el4[12 + k] - half);
        hull.hi[k] = Math.max(hull.hi[k], el4[12 + k] + half);
      }
    }
    function pushVolume(v, box, sphere, cyl, hull) {
      if (v.kind === 'box') {
        const lo = new THREE.Vector3().fromArray(v.lo), hi = new THREE.Vector3().fromArray(v.hi);
        pushBox(box, pos.copy(lo).add(hi).multiplyScalar(0.5), ident, scale.copy(hi).sub(lo), hull);
      } else if (v.kind === 'oriented_box') {
        axisX.fromArray(v.axes, 0); axisY.fromArray(v.axes, 3); axisZ.fromArray(v.axes, 6);
        // A box is symmetric: a left-handed frame is the right-handed one with an axis flipped.
        if (axisX.clone().cross(axisY).dot(axisZ) < 0) axisZ.negate();
        basis.makeBasis(axisX, axisY, axisZ);
        quat.setFromRotationMatrix(basis);
        pushBox(box, pos.fromArray(v.c), quat, scale.fromArray(v.half).multiplyScalar(2), hull);
      } else if (v.kind === 'sphere') {
        pos.fromArray(v.c);
        sphere.push(pos, ident, scale.set(v.r, v.r, v.r));
        mergeBall(hull, pos, v.r);
      } else if (v.kind === 'capsule') {
        const a = new THREE.Vector3().fromArray(v.a), b = new THREE.Vector3().fromArray(v.b);
        sphere.push(a, ident, scale.set(v.r, v.r, v.r));
        sphere.push(b, ident, scale.set(v.r, v.r, v.r));
        mergeBall(hull, a, v.r);
        mergeBall(hull, b, v.r);
        const d = b.clone().sub(a), len = d.length();
        if (len > 0) {
          quat.setFromUnitVectors(up, d.clone().multiplyScalar(1 / len));
          cyl.push(pos.copy(a).add(b).multiplyScalar(0.5), quat, scale.set(v.r, len, v.r));
        }
      }
    }

    // Draws body i's volumes of `run` at t; returns what the page read back for it
    // ({window, kinds, lo, hi}), or null where the page holds none.
    function drawBodyVolumes(run, i, t, box, sphere, cyl) {
      const entry = volumeEntry(run, i, t);
      if (!entry) return null;
      const hull = { lo: [Infinity, Infinity, Infinity], hi: [-Infinity, -Infinity, -Infinity] };
      for (const v of entry[2]) pushVolume(v, box, sphere, cyl, hull);
      return { window: [entry[0], entry[1]], kinds: entry[2].map((v) => v.kind), lo: hull.lo, hi: hull.hi };
    }

    updateScene = function () {
      const t = state.t;
      for (const g of groups) {
        if (g.points) {
          const arr = g.points.geometry.attributes.position.array;
          g.members.forEach((i, slot) => {
            motion.position(i, t, pos);
            arr[3 * slot] = pos.x; arr[3 * slot + 1] = pos.y; arr[3 * slot + 2] = pos.z;
          });
          g.points.geometry.attributes.position.needsUpdate = true;
          g.points.material.uniforms.scale.value = renderer.getDrawingBufferSize(new THREE.Vector2()).y /
            (2 * Math.tan(camera.fov * Math.PI / 360));
          continue;
        }
        if (!g.mesh) continue;
        g.members.forEach((i, slot) => {
          motion.position(i, t, pos);
          centres[3 * i] = pos.x; centres[3 * i + 1] = pos.y; centres[3 * i + 2] = pos.z;
          if (g.scaled) { const r = motion.radius[i]; m4.compose(pos, ident, scale.set(r, r, r)); }
          else m4.compose(pos, motion.orientation(i, t, quat), one);
          g.mesh.setMatrixAt(slot, m4);
        });
        g.mesh.instanceMatrix.needsUpdate = true;
      }
      // Highlighted pair, its bodies at the start of their windows (the state each bound was
      // built from), their paths over the windows, their bounds.
      const run = state.run, pair = state.pair;
      const windowOf = (i) => {
        const entry = run ? volumeEntry(run, i, t) : null;
        if (entry) return { t0: entry[0], t1: entry[1] };
        return run ? stepAt(run, t) : null;
      };
      for (let k = 0; k < 2; ++k) {
        const i = pair && k < pair.length ? pair[k] : -1;
        highlight[k].visible = i >= 0;
        ghosts[k].visible = false;
        if (i < 0) continue;
        const s = motion.shape[i];
        const g = groups[s < 0 ? 0 : shapeGroup[s]];
        highlight[k].geometry = g.geometry;
        motion.position(i, t, highlight[k].position);
        if (g.scaled) { highlight[k].quaternion.set(0, 0, 0, 1); highlight[k].scale.setScalar(motion.radius[i]); }
        else { motion.orientation(i, t, highlight[k].quaternion); highlight[k].scale.setScalar(1); }
        const w = windowOf(i);
        if (w && el('show-samples').checked) {
          ghosts[k].visible = true;
          ghosts[k].geometry = g.geometry;
          motion.position(i, w.t0, ghosts[k].position);
          if (g.scaled) { ghosts[k].quaternion.set(0, 0, 0, 1); ghosts[k].scale.setScalar(motion.radius[i]); }
          else { motion.orientation(i, w.t0, ghosts[k].quaternion); ghosts[k].scale.setScalar(1); }
        }
      }
      pathLines.visible = !!(pair && run);
      if (pathLines.visible) {
        const arr = pathGeo.attributes.position.array;
        let c = 0;
        for (const i of pair) {
          const w = windowOf(i);
          for (let j = 0; j < PATH_POINTS; ++j) {
            for (const u of [j, j + 1]) {
              motion.position(i, w.t0 + (w.t1 - w.t0) * u / PATH_POINTS, pos);
              arr[c++] = pos.x; arr[c++] = pos.y; arr[c++] = pos.z;
            }
          }
        }
        pathGeo.attributes.position.needsUpdate = true;
        pathGeo.setDrawRange(0, c / 3);  // one body's path for a body-scenery contact
      }
      for (const p of Object.values(pools)) p.begin();
      let pairText = '';
      const drawn = {};
      if (run && pair && el('show-bounds').checked) {
        const missing = [];
        for (const i of pair) {
          const d = drawBodyVolumes(run, i, t, pools.pairBox, pools.pairSphere, pools.pairCyl);
          if (d) drawn[i] = d; else missing.push(i);
        }
        const shown = pair.filter((i) => drawn[i]).map((i) => 'body ' + i + ' over [' +
          formatNumber(drawn[i].window[0]) + ', ' + formatNumber(drawn[i].window[1]) + ']');
        pairText = (shown.length ? 'bounds of ' + shown.join(', ') : '') +
          (missing.length ? (shown.length ? '; ' : '') + 'no bounds in the page here for body ' + missing.join(', ') +
            (volumesNote(run) ? ' (' + volumesNote(run) + ')' : '') : '');
      }
      if (run && el('show-all-bounds').checked) {
        for (let i = 0; i < n; ++i) {
          if (pair && pair.indexOf(i) >= 0 && el('show-bounds').checked) continue;  // drawn above
          const d = drawBodyVolumes(run, i, t, pools.box, pools.sphere, pools.cyl);
          if (d) drawn[i] = d;
        }
      }
      // What was drawn, for tests (tests/viewer/browser_test.py): per body its window, the
      // kinds of its volumes and the world box of the drawn instances.
      if (n <= 2000) body.dataset.volumes = JSON.stringify(drawn);
      for (const p of Object.values(pools)) p.end(true);
      sceneryHighlight(state.polygon !== null && pair && pair.length === 1 ? state.polygon : null);
      if (pair && pair.length === 1) {
        // A body and a scenery polygon: the body's distance to the polygon's plane less its radius.
        const i = pair[0], j = state.polygon;
        const c = motion.position(i, t, new THREE.Vector3());
        const gap = j !== null && plane[j] ? Math.abs(plane[j].n.dot(c) - plane[j].d) - motion.radius[i] : NaN;
        body.dataset.pairGap = String(gap);
        el('pair-info').textContent = 'body ' + i + ' and scenery polygon ' + j + ': distance to its plane - radius = ' +
          gap.toPrecision(4) + (motion.shape[i] >= 0 ? ' (enclosing ball)' : '') + (pairText ? '; ' + pairText : '');
      } else if (pair) {
        const a = motion.position(pair[0], t, new THREE.Vector3()), b = motion.position(pair[1], t, new THREE.Vector3());
        const gap = a.distanceTo(b) - motion.radius[pair[0]] - motion.radius[pair[1]];
        body.dataset.pairGap = String(gap);
        el('pair-info').textContent = 'pair ' + pair[0] + '-' + pair[1] + ': centre distance - radii = ' +
          gap.toPrecision(4) + (motion.shape[pair[0]] >= 0 || motion.shape[pair[1]] >= 0 ? ' (enclosing balls)' : '') +
          (pairText ? '; ' + pairText : '');
        if (state.focusPair) {
          // Frame the pair over its windows: where the method saw it and where it is now.
          state.focusPair = false;
          const min = new THREE.Vector3(Infinity, Infinity, Infinity), max = min.clone().negate();
          for (const i of pair) {
            const r = motion.radius[i];
            const w = windowOf(i);
            for (const u of w ? [t, w.t0, w.t1] : [t]) {
              motion.position(i, u, pos);
              min.min(pos.clone().addScalar(-2 * r));
              max.max(pos.clone().addScalar(2 * r));
            }
          }
          frameView(min, max);
        }
      } else {
        delete body.dataset.pairGap;
        el('pair-info').textContent = '';
      }
      // Truth's contacts in progress at t.
      let c = 0;
      const showTruth = el('show-truth').checked;
      const active = [];
      if (showTruth) for (const e of truth) if (e[2] <= t && t <= e[3]) active.push(e);
      const activeStatic = [];
      if (showTruth) for (const e of staticTruth) if (e[2] <= t && t <= e[3]) activeStatic.push(e);
      if (2 * (active.length + activeStatic.length) > contactCapacity) {
        contactCapacity = Math.max(64, 4 * (active.length + activeStatic.length));
        contactGeo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * contactCapacity), 3));
      }
      if (contactCapacity) {
        const arr = contactGeo.attributes.position.array;
        for (const e of active) {
          for (const i of [e[0], e[1]]) {
            motion.position(i, t, pos);
            arr[3 * c] = pos.x; arr[3 * c + 1] = pos.y; arr[3 * c + 2] = pos.z; ++c;
          }
        }
        for (const e of activeStatic) {  // the body's centre to the nearest point of the polygon's plane
          motion.position(e[0], t, pos);
          arr[3 * c] = pos.x; arr[3 * c + 1] = pos.y; arr[3 * c + 2] = pos.z; ++c;
          const q = plane[e[1]];
          pos.addScaledVector(q.n, q.d - q.n.dot(pos));
          arr[3 * c] = pos.x; arr[3 * c + 1] = pos.y; arr[3 * c + 2] = pos.z; ++c;
        }
        contactGeo.attributes.position.needsUpdate = true;
        contactGeo.setDrawRange(0, c);
      }
      contactLines.visible = showTruth && c > 0;
      if (layers.walls) layers.walls.visible = el('show-box').checked;
      if (layers.scenery) layers.scenery.visible = el('show-scenery').checked;
      body.dataset.contacts = String(active.length + activeStatic.length);
    };

    // Initial view: the walls, else the bodies at t = 0.
    if (data.box) {
      addWalls(data.box);
      frameView(new THREE.Vector3().fromArray(data.box.min), new THREE.Vector3().fromArray(data.box.max));
    } else {
      const min = new THREE.Vector3(Infinity, Infinity, Infinity), max = min.clone().negate();
      for (let i = 0; i < n; ++i) {
        motion.position(i, 0, pos);
        min.min(pos.clone().addScalar(-motion.radius[i]));
        max.max(pos.clone().addScalar(motion.radius[i]));
      }
      const sc = data.scenery || [];
      for (const f of sc)
        for (let k = 0; k < f.length; k += 3) { min.min(pos.fromArray(f, k)); max.max(pos); }
      if (n || sc.length) frameView(min, max);
    }
    el('legend').innerHTML = '<span style="background:#6d8fb3"></span>bodies <span style="background:#f00"></span>highlighted pair' +
      ' <span style="background:#d03030;opacity:0.5"></span>its bounds <span style="background:#e8a020"></span>bounds' +
      ' <span style="background:#109030"></span>truth contact' +
      ((data.scenery || []).length ? ' <span style="background:#9c8f6a"></span>scenery' : '');
  }

  function makeCloth3D() {
    const frames = data.frames;
    const np = data.nx * data.ny;
    const geo = new THREE.BufferGeometry();
    const positions = new Float32Array(3 * np);
    geo.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    geo.setIndex(data.triangles);
    const mesh = new THREE.Mesh(geo, new THREE.MeshLambertMaterial({ color: 0x5b8fd0, side: THREE.DoubleSide }));
    mesh.frustumCulled = false;
    scene3.add(mesh);
    const wire = new THREE.Mesh(geo, new THREE.MeshBasicMaterial({ color: 0x1d3f70, wireframe: true }));
    wire.frustumCulled = false;
    scene3.add(wire);
    for (const s of data.spheres || []) {
      const m = new THREE.Mesh(new THREE.SphereBufferGeometry(s.radius, 32, 16), new THREE.MeshLambertMaterial({ color: 0xb0b0b0 }));
      m.position.fromArray(s.center);
      scene3.add(m);
    }
    const min = new THREE.Vector3(Infinity, Infinity, Infinity), max = min.clone().negate();
    for (const f of frames) for (let k = 0; k < f.x.length; k += 3) {
      min.min(new THREE.Vector3(f.x[k], f.x[k + 1], f.x[k + 2]));
      max.max(new THREE.Vector3(f.x[k], f.x[k + 1], f.x[k + 2]));
    }
    if (data.floor !== null && data.floor !== undefined) {
      const size = Math.max(max.x - min.x, max.z - min.z) * 2;
      const floor = new THREE.Mesh(new THREE.PlaneBufferGeometry(size, size), new THREE.MeshLambertMaterial({ color: 0xd8d2c0, side: THREE.DoubleSide }));
      floor.rotation.x = -Math.PI / 2;
      floor.position.set((min.x + max.x) / 2, data.floor, (min.z + max.z) / 2);
      scene3.add(floor);
    }
    frameView(min, max);
    updateScene = function () {
      const t = state.t;
      let k = 0;
      while (k + 1 < frames.length && frames[k + 1].t <= t) ++k;
      const a = frames[k], b = frames[Math.min(k + 1, frames.length - 1)];
      const w = b.t > a.t ? Math.min(1, Math.max(0, (t - a.t) / (b.t - a.t))) : 0;
      for (let i = 0; i < 3 * np; ++i) positions[i] = a.x[i] + w * (b.x[i] - a.x[i]);
      geo.attributes.position.needsUpdate = true;
      geo.computeVertexNormals();
      body.dataset.frame = String(k);
    };
    el('legend').textContent = data.nx + ' x ' + data.ny + ' particles, ' + frames.length + ' frames (linear in between)';
  }

  function render() {
    updateScene();
    renderer.render(scene3, camera);
    el('time-text').textContent = 't = ' + state.t.toFixed(6) + ' s';
    drawTimeline();
    state.dirty = false;
  }

  function loop(now) {
    if (state.playing) {
      if (lastFrame !== null) {
        const t = state.t + (now - lastFrame) / 1000 * state.speed;
        if (t >= data.horizon) { state.playing = false; }
        setTime(Math.min(t, data.horizon));
      }
      lastFrame = now;
    } else {
      lastFrame = null;
    }
    el('play').textContent = state.playing ? 'Pause' : 'Play';
    if (state.dirty) render();
    window.requestAnimationFrame(loop);
  }

  // Frame time: `#bench=N` renders N frames at times spread over the horizon, each forced to
  // finish (a pixel read), and writes the mean and the median in ms to <output id="bench">.
  function bench(frames) {
    const gl = renderer.getContext();
    const pixel = new Uint8Array(4);
    const times = [], updates = [];
    for (let f = 0; f < frames; ++f) {
      const start = performance.now();
      state.t = data.horizon * (f + 0.5) / frames;
      updateScene();
      const updated = performance.now();
      renderer.render(scene3, camera);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      times.push(performance.now() - start);
      updates.push(updated - start);
    }
    const median = (xs) => xs.slice().sort((x, y) => x - y)[xs.length >> 1].toFixed(2);
    const out = el('bench');
    out.dataset.frames = String(frames);
    out.dataset.medianMs = median(times);
    out.dataset.updateMs = median(updates);
    out.textContent = 'frame time: median ' + out.dataset.medianMs + ' ms over ' + frames + ' frames (of which ' +
      out.dataset.updateMs + ' ms evaluating the motion)';
  }

  // ---------------------------------------------------------------- start
  function main() {
    const f = readFragment();
    body.dataset.kind = data.kind;
    el('info').textContent = data.kind === 'cloth'
      ? 'cloth frames ' + data.scene_file + ', ' + data.frames.length + ' frames over ' + formatNumber(data.horizon) + ' s'
      : data.scene_file + ': ' + data.bodies.count + ' bodies over ' + formatNumber(data.horizon) + ' s' +
        ((data.scenery || []).length ? ', ' + data.scenery.length + ' scenery polygons' : '') +
        (data.truth ? ', ' + data.truth.length + ' body-body' + (data.static_truth && data.static_truth.length
          ? ' and ' + data.static_truth.length + ' body-scenery' : '') + ' truth contacts' : ', no truth given (--truth)') +
        (data.results_file ? ', results ' + data.results_file : '');
    body.dataset.bodies = String(data.kind === 'cloth' ? 0 : data.bodies.count);
    fillRunControls();
    setupTimeControls();
    if (methods.length) {
      const method = f.method !== undefined && methods.indexOf(f.method) >= 0 ? f.method : methods[0];
      selectRun(method, f.dt !== undefined ? Number(f.dt) : null, false);
      body.dataset.method = state.run.method;
      body.dataset.dt = String(state.run.dt);
    }
    if (f.t !== undefined && isFinite(Number(f.t))) setTime(Number(f.t));
    if (f.pair && data.kind === 'bodies') {
      const ab = f.pair.split('-').map(Number);
      if (ab.length === 2 && ab.every((x) => Number.isInteger(x) && x >= 0 && x < data.bodies.count)) {
        const list = missedOf(state.run) || [];
        state.missedIndex = list.findIndex((m) => m.a === ab[0] && m.b === ab[1] && m.enter <= state.t && state.t <= m.exit);
        setPair(ab, true);
      }
    }
    for (const id of ['show-bounds', 'show-all-bounds', 'show-samples', 'show-truth', 'show-box', 'show-scenery'])
      el(id).addEventListener('change', () => { state.dirty = true; });
    if (data.kind === 'bodies' && data.bodies.count > 2000) el('show-all-bounds').checked = false;
    if (f.bounds === 'all' || f.bounds === 'pair' || f.bounds === 'none') {
      el('show-bounds').checked = f.bounds !== 'none';
      el('show-all-bounds').checked = f.bounds === 'all';
    }
    try {
      make3D();
    } catch (e) {
      const msg = el('message');
      msg.hidden = false;
      msg.textContent = 'WebGL is not available here, so the scene is not drawn; the table works. (' + e.message + ')';
      body.dataset.status = 'no-webgl';
      state.fragmentReady = true;
      return;
    }
    if (data.kind === 'cloth') makeCloth3D(); else makeBodies3D();
    render();
    state.fragmentReady = true;
    if (f.bench) bench(Math.max(1, Math.min(1000, parseInt(f.bench, 10) || 60)));
    body.dataset.status = 'ready';
    window.requestAnimationFrame(loop);
  }

  try {
    main();
  } catch (e) {
    body.dataset.status = 'error';
    body.dataset.error = String(e && e.message || e);
    const msg = el('message');
    msg.hidden = false;
    msg.textContent = 'The page failed: ' + body.dataset.error;
  }
})();
