// hinge view: the page's script. It reads the run (the JSON element #hinge-run: hinge/view/page.hpp and
// encoding.hpp say how it is encoded), draws frame after frame with three.js's WebGL renderer, or on a 2D
// canvas where WebGL is unavailable, and wires the controls. The address's #frame=N opens frame N (paused);
// #frame=N&draw=2d draws on the 2D canvas even where WebGL is there.
(function () {
  'use strict';

  const run = JSON.parse(document.getElementById('hinge-run').textContent);
  const hash = new URLSearchParams(location.hash.slice(1));

  // --- The run's arrays -------------------------------------------------------------------------------
  function bytes(base64) {
    const text = atob(base64);
    const out = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) out[i] = text.charCodeAt(i);
    return out;
  }
  const faces = new Int32Array(bytes(run.faces).buffer);
  const faceHinges = new Int32Array(bytes(run.face_hinges).buffer);  // per face, the hinge on edge i, or -1
  const faceCount = faces.length / 3;
  const frameCount = run.times.length;
  const level = [0, 1, 2].map((c) => (run.box.max[c] - run.box.min[c]) / (run.position_levels - 1));

  const positionCache = new Map();
  function positions(frame) {  // Float32Array(3 n) of frame `frame`
    let p = positionCache.get(frame);
    if (p) return p;
    const q = new Uint16Array(bytes(run.positions[frame]).buffer);
    p = new Float32Array(q.length);
    for (let i = 0; i < q.length; ++i) p[i] = run.box.min[i % 3] + q[i] * level[i % 3];
    positionCache.set(frame, p);
    return p;
  }
  const valueCache = new Map();
  function values(frame) {  // Uint8Array(hinges): the levels of |theta - theta_bar|, 255 for no value
    let v = valueCache.get(frame);
    if (!v) valueCache.set(frame, (v = bytes(run.values[frame])));
    return v;
  }

  // --- Colours: a blue-purple-orange-yellow scale, dark to light, every level a saturated colour ---------
  const anchors = [[0.05, 0.03, 0.53], [0.49, 0.01, 0.66], [0.80, 0.28, 0.47], [0.97, 0.58, 0.25], [0.94, 0.98, 0.13]];
  function scaleColour(t) {
    const x = Math.min(Math.max(t, 0), 1) * (anchors.length - 1);
    const i = Math.min(Math.floor(x), anchors.length - 2), f = x - i;
    return [0, 1, 2].map((c) => anchors[i][c] * (1 - f) + anchors[i + 1][c] * f);
  }
  const noHinge = [0.82, 0.82, 0.82], noValue = [0.35, 0.35, 0.35];
  const levelColours = [];
  for (let l = 0; l < run.value_levels; ++l) levelColours.push(scaleColour(l / (run.value_levels - 1)));
  levelColours.push(noValue);

  // Each face drawn as three triangles, one per edge, from the edge to the face's centroid: the hinge on
  // that edge colours it (a hinge's two triangles make the diamond around its edge); boundary edges grey.
  function fillTriangles(frame, xyz, rgb) {
    const p = positions(frame), v = values(frame);
    for (let f = 0; f < faceCount; ++f) {
      const a = 3 * faces[3 * f], b = 3 * faces[3 * f + 1], c = 3 * faces[3 * f + 2];
      const corner = [a, b, c];
      const centroid = [0, 1, 2].map((k) => (p[a + k] + p[b + k] + p[c + k]) / 3);
      for (let e = 0; e < 3; ++e) {
        const o = 27 * f + 9 * e, from = corner[(e + 1) % 3], to = corner[(e + 2) % 3];
        const h = faceHinges[3 * f + e];
        const colour = h < 0 ? noHinge : levelColours[v[h]];
        for (let k = 0; k < 3; ++k) {
          xyz[o + k] = centroid[k];
          xyz[o + 3 + k] = p[from + k];
          xyz[o + 6 + k] = p[to + k];
          rgb[o + k] = rgb[o + 3 + k] = rgb[o + 6 + k] = colour[k];
        }
      }
    }
  }

  // --- The view: fitted to the bounding box of all frames, seen from above at 35 degrees ----------------
  const up = normalized(run.up);
  const centre = [0, 1, 2].map((c) => (run.box.min[c] + run.box.max[c]) / 2);
  const radius = Math.max(Math.hypot(...[0, 1, 2].map((c) => run.box.max[c] - run.box.min[c])) / 2, 1e-9);
  const fov = 35;  // degrees, vertical
  function normalized(v) {
    const l = Math.hypot(v[0], v[1], v[2]) || 1;
    return [v[0] / l, v[1] / l, v[2] / l];
  }
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
  const side = (function () {  // a horizontal direction to look from
    for (const a of [[0.5, -1, 0], [1, 0, 0], [0, 1, 0]]) {
      const d = dot(a, up), h = [a[0] - d * up[0], a[1] - d * up[1], a[2] - d * up[2]];
      if (Math.hypot(...h) > 0.1) return normalized(h);
    }
    return [1, 0, 0];
  })();
  const elevation = (35 * Math.PI) / 180;
  const initialBack = [0, 1, 2].map((c) => Math.cos(elevation) * side[c] + Math.sin(elevation) * up[c]);
  // The camera's axes when it looks from the direction `back` (unit, from the centre towards the eye), as
  // three.js's lookAt makes them: right = up x back, vertical = back x right.
  function cameraAxes(back) {
    let right = normalized(cross(up, back));
    if (Math.hypot(...right) < 0.5) right = side;  // looking along up
    return [right, cross(back, right)];
  }
  // The least distance from the centre at which every corner of the box of all frames is in view (with a
  // margin of 5%), looking from `back`.
  function fittedDistance(aspect, back) {
    const [right, vertical] = cameraAxes(back);
    const ty = 0.95 * Math.tan((fov * Math.PI) / 360), tx = ty * aspect;
    let d = 0;
    for (let k = 0; k < 8; ++k) {
      const p = [0, 1, 2].map((c) => ((k >> c) & 1 ? run.box.max[c] : run.box.min[c]) - centre[c]);
      const z = dot(p, back);
      d = Math.max(d, z + Math.abs(dot(p, right)) / tx, z + Math.abs(dot(p, vertical)) / ty);
    }
    return d > 0 ? d : radius;
  }

  // --- Controls and state ---------------------------------------------------------------------------------
  const view = document.getElementById('view');
  const slider = document.getElementById('slider');
  const play = document.getElementById('play');
  const timeLabel = document.getElementById('time');
  const status = document.getElementById('status');
  document.title = run.name + ' (hinge view)';
  slider.max = String(frameCount - 1);
  status.textContent = run.name + ': ' + run.status + (run.reason ? ' (' + run.reason + ')' : '');
  status.title = status.textContent;  // in full where it is cut short
  if (run.status !== 'ok') status.className = 'failed';
  let current = -1, playing = false, renderer = null;

  function showFrame(frame) {
    current = Math.min(Math.max(frame | 0, 0), frameCount - 1);
    slider.value = String(current);
    timeLabel.textContent = run.dynamic
      ? 't = ' + run.times[current].toFixed(3) + ' s, frame ' + current + ' of ' + (frameCount - 1)
      : 'static equilibrium';
    renderer.setFrame(current);
    document.body.dataset.frame = String(current);
  }
  function setPlaying(on) {
    playing = on && frameCount > 1;
    play.textContent = playing ? 'Pause' : 'Play';
    if (playing) requestAnimationFrame(tick);
  }
  let last = 0;
  function tick(now) {
    if (!playing) return;
    if (now - last >= 50) {  // 20 frames a second
      last = now;
      showFrame(current + 1 < frameCount ? current + 1 : 0);
    }
    requestAnimationFrame(tick);
  }
  play.addEventListener('click', () => setPlaying(!playing));
  slider.addEventListener('input', () => {
    setPlaying(false);
    showFrame(Number(slider.value));
  });
  window.addEventListener('hashchange', () => {
    const h = new URLSearchParams(location.hash.slice(1));
    if (h.has('frame')) {
      setPlaying(false);
      showFrame(Number(h.get('frame')));
    }
  });

  // --- The colour bar: one scale for all frames, 0 to the largest |theta - theta_bar| -------------------
  (function () {
    const canvas = document.getElementById('bar-colours'), g = canvas.getContext('2d');
    for (let y = 0; y < canvas.height; ++y) {
      const c = scaleColour(1 - y / (canvas.height - 1)).map((x) => Math.round(255 * x));
      g.fillStyle = 'rgb(' + c.join(',') + ')';
      g.fillRect(0, y, 1, 1);
    }
    const labels = document.getElementById('bar-labels');
    for (const t of [0, 0.25, 0.5, 0.75, 1]) {
      const span = document.createElement('span');
      span.style.top = 100 * (1 - t) + '%';
      span.textContent = Number((t * run.scale).toPrecision(3)).toString();
      labels.appendChild(span);
    }
  })();

  // --- WebGL through three.js ----------------------------------------------------------------------------
  function webglRenderer() {
    const gl = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});  // throws without WebGL
    gl.setPixelRatio(window.devicePixelRatio || 1);
    view.appendChild(gl.domElement);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xf2f2f2);
    const camera = new THREE.PerspectiveCamera(fov, 1, radius / 100, radius * 100);
    camera.up.set(up[0], up[1], up[2]);
    scene.add(new THREE.AmbientLight(0xffffff, 0.55));
    const light = new THREE.DirectionalLight(0xffffff, 0.5);  // follows the camera
    scene.add(light, light.target);

    const geometry = new THREE.BufferGeometry();
    const xyz = new Float32Array(27 * faceCount), rgb = new Float32Array(27 * faceCount);
    geometry.setAttribute('position', new THREE.BufferAttribute(xyz, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(rgb, 3));
    const material = new THREE.MeshLambertMaterial({vertexColors: THREE.VertexColors, side: THREE.DoubleSide});
    scene.add(new THREE.Mesh(geometry, material));
    if (run.sphere) {
      const ball = new THREE.Mesh(new THREE.SphereBufferGeometry(run.sphere.radius, 64, 32),
                                  new THREE.MeshLambertMaterial({color: 0x9a9a9a}));
      ball.position.set(...run.sphere.center);
      scene.add(ball);
    }
    const controls = new THREE.OrbitControls(camera, gl.domElement);
    controls.target.set(...centre);

    function draw() {
      light.position.copy(camera.position);
      light.target.position.copy(controls.target);
      gl.render(scene, camera);
    }
    function resize() {
      const w = view.clientWidth || 1, h = view.clientHeight || 1;
      gl.setSize(w, h, false);
      camera.aspect = w / h;
      camera.updateProjectionMatrix();
      draw();
    }
    const d = fittedDistance(Math.max(view.clientWidth, 1) / Math.max(view.clientHeight, 1), initialBack);
    camera.position.set(...[0, 1, 2].map((c) => centre[c] + d * initialBack[c]));
    controls.update();
    controls.addEventListener('change', draw);
    window.addEventListener('resize', resize);
    resize();
    return {
      name: 'webgl',
      setFrame(frame) {
        fillTriangles(frame, xyz, rgb);
        geometry.attributes.position.needsUpdate = true;
        geometry.attributes.color.needsUpdate = true;
        geometry.computeVertexNormals();  // not indexed: each triangle's own normal
        geometry.computeBoundingSphere();
        draw();
      },
    };
  }

  // --- The 2D fallback: the same triangles, depth-sorted, flat-shaded ---------------------------------------
  function canvasRenderer() {
    const canvas = document.createElement('canvas');
    view.appendChild(canvas);
    const g = canvas.getContext('2d');
    const xyz = new Float32Array(27 * faceCount), rgb = new Float32Array(27 * faceCount);
    const forward = cross(up, side);  // with side and up, an orthonormal frame about the centre
    let azimuth = 0, tilt = elevation, distance = 0, frameShown = -1;

    function eye() {
      const h = [0, 1, 2].map((c) => Math.cos(azimuth) * side[c] + Math.sin(azimuth) * forward[c]);
      return [0, 1, 2].map((c) => centre[c] + distance * (Math.cos(tilt) * h[c] + Math.sin(tilt) * up[c]));
    }
    function draw() {
      const w = canvas.width, hgt = canvas.height, e = eye();
      const back = normalized([0, 1, 2].map((c) => e[c] - centre[c]));  // camera's +z
      const [right, vertical] = cameraAxes(back);
      const focal = hgt / 2 / Math.tan((fov * Math.PI) / 360);
      const project = (p) => {
        const r = [p[0] - e[0], p[1] - e[1], p[2] - e[2]];
        const z = -dot(r, back);
        return [w / 2 + (focal * dot(r, right)) / z, hgt / 2 - (focal * dot(r, vertical)) / z, z];
      };
      const count = 3 * faceCount, items = [];
      for (let t = 0; t < count; ++t) items.push(t);
      const depth = new Float32Array(count + 1), screen = new Float32Array(6 * count), shade = new Float32Array(count);
      for (let t = 0; t < count; ++t) {
        const o = 9 * t;
        const a = [xyz[o], xyz[o + 1], xyz[o + 2]], b = [xyz[o + 3], xyz[o + 4], xyz[o + 5]],
              c = [xyz[o + 6], xyz[o + 7], xyz[o + 8]];
        let z = 0;
        [a, b, c].forEach((p, k) => {
          const s = project(p);
          screen[6 * t + 2 * k] = s[0];
          screen[6 * t + 2 * k + 1] = s[1];
          z += s[2] / 3;
        });
        depth[t] = z;
        const n = normalized(cross([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]));
        shade[t] = 0.55 + 0.5 * Math.abs(dot(n, back));  // ambient and a headlight, both sides lit
      }
      if (run.sphere) {
        depth[count] = project(run.sphere.center)[2];
        items.push(count);
      }
      items.sort((i, j) => depth[j] - depth[i]);
      g.fillStyle = '#f2f2f2';
      g.fillRect(0, 0, w, hgt);
      g.lineWidth = 0.5;
      g.lineJoin = 'round';
      for (const t of items) {
        if (t === count) {  // the sphere, as a shaded disc
          const s = project(run.sphere.center), r = (focal * run.sphere.radius) / s[2];
          const fill = g.createRadialGradient(s[0] - r / 3, s[1] - r / 3, r / 10, s[0], s[1], r);
          fill.addColorStop(0, '#d8d8d8');
          fill.addColorStop(1, '#8c8c8c');
          g.fillStyle = fill;
          g.beginPath();
          g.arc(s[0], s[1], r, 0, 2 * Math.PI);
          g.fill();
          continue;
        }
        if (depth[t] <= 0) continue;  // behind the eye
        const k = Math.min(shade[t], 1), o = 9 * t;
        const colour = 'rgb(' + Math.round(255 * k * rgb[o]) + ',' + Math.round(255 * k * rgb[o + 1]) + ',' +
                       Math.round(255 * k * rgb[o + 2]) + ')';
        g.fillStyle = g.strokeStyle = colour;
        g.beginPath();
        g.moveTo(screen[6 * t], screen[6 * t + 1]);
        g.lineTo(screen[6 * t + 2], screen[6 * t + 3]);
        g.lineTo(screen[6 * t + 4], screen[6 * t + 5]);
        g.closePath();
        g.fill();
        g.stroke();  // hides the seams between neighbours
      }
    }
    function resize() {
      const ratio = window.devicePixelRatio || 1;
      canvas.width = Math.max(1, Math.round(view.clientWidth * ratio));
      canvas.height = Math.max(1, Math.round(view.clientHeight * ratio));
      if (frameShown >= 0) draw();
    }
    let drag = null;
    canvas.addEventListener('pointerdown', (e) => {
      drag = [e.clientX, e.clientY, azimuth, tilt];
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!drag) return;
      azimuth = drag[2] - (e.clientX - drag[0]) * 0.01;
      tilt = Math.min(Math.max(drag[3] + (e.clientY - drag[1]) * 0.01, -1.5), 1.5);
      draw();
    });
    canvas.addEventListener('pointerup', () => (drag = null));
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      distance *= Math.exp(e.deltaY * 0.001);
      draw();
    }, {passive: false});
    window.addEventListener('resize', resize);
    resize();
    distance = fittedDistance(canvas.width / canvas.height, initialBack);
    return {
      name: '2d',
      setFrame(frame) {
        fillTriangles(frame, xyz, rgb);
        frameShown = frame;
        draw();
      },
    };
  }

  // --- Start: WebGL where it works, else the 2D canvas; paused at #frame=N, else playing ------------------
  if (hash.get('draw') !== '2d') {
    try {
      renderer = webglRenderer();
    } catch (e) {
      renderer = null;
      view.textContent = '';
    }
  }
  if (!renderer) renderer = canvasRenderer();
  document.body.dataset.renderer = renderer.name;
  showFrame(hash.has('frame') ? Number(hash.get('frame')) : 0);
  document.body.dataset.readyMs = performance.now().toFixed(0);
  setPlaying(!hash.has('frame'));
})();
