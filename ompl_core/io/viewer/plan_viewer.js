// The plan viewer of ompl_mm and ompl_phys: draws the plan data of the page (the JSON in
// <script id="plan-data">, written by ompl_core::writePlanViewerPage) with three.js, z up, and animates
// it frame by frame. The URL's hash may set the start: "#at=0.5" (a fraction of the timeline),
// "paused" and "zoom=2" (the camera twice as close); the page marks <body data-ready="1"> once the
// first picture is drawn.
(function () {
  'use strict';
  const plan = JSON.parse(document.getElementById('plan-data').textContent);
  THREE.Object3D.DefaultUp.set(0, 0, 1);

  // --- the world ------------------------------------------------------------------------------------
  const view = document.getElementById('view');
  const renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  view.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf7f7f4);
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  const sun = new THREE.DirectionalLight(0xffffff, 0.65);
  sun.position.set(0.4, -0.6, 1.0);
  scene.add(sun);

  // faces meeting at more than this angle show a sharp edge; within a surface shading is smooth
  const CREASE_COS = Math.cos(40 * Math.PI / 180);
  // a mesh of more triangles (a robot's detailed visual mesh) gets no edge lines: they would scribble on it
  const MAX_OUTLINED_TRIANGLES = 1000;

  // a triangle soup with a normal per corner: the area-weighted mean of the normals of the faces
  // around its vertex that lie within the crease angle of its own face
  function creasedGeometry(positions, indices) {
    const faces = indices.length / 3, vertexCount = positions.length / 3;
    const areaNormals = new Float64Array(faces * 3), unitNormals = new Float64Array(faces * 3);
    const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3();
    for (let f = 0; f < faces; ++f) {
      a.fromArray(positions, 3 * indices[3 * f]);
      b.fromArray(positions, 3 * indices[3 * f + 1]).sub(a);
      c.fromArray(positions, 3 * indices[3 * f + 2]).sub(a);
      b.cross(c);
      b.toArray(areaNormals, 3 * f);
      b.normalize().toArray(unitNormals, 3 * f);
    }
    // the faces around each vertex, as one array with an offset per vertex
    const start = new Int32Array(vertexCount + 1);
    for (const v of indices) ++start[v + 1];
    for (let v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
    const filled = start.slice(0, vertexCount), around = new Int32Array(indices.length);
    for (let i = 0; i < indices.length; ++i) around[filled[indices[i]]++] = Math.floor(i / 3);
    const outPositions = new Float32Array(faces * 9), outNormals = new Float32Array(faces * 9);
    for (let i = 0; i < indices.length; ++i) {
      const v = indices[i], f = Math.floor(i / 3);
      let x = 0, y = 0, z = 0;
      for (let k = start[v]; k < start[v + 1]; ++k) {
        const g = around[k];
        if (unitNormals[3 * f] * unitNormals[3 * g] + unitNormals[3 * f + 1] * unitNormals[3 * g + 1] +
            unitNormals[3 * f + 2] * unitNormals[3 * g + 2] < CREASE_COS) continue;
        x += areaNormals[3 * g]; y += areaNormals[3 * g + 1]; z += areaNormals[3 * g + 2];
      }
      const length = Math.hypot(x, y, z) || 1;
      outNormals[3 * i] = x / length; outNormals[3 * i + 1] = y / length; outNormals[3 * i + 2] = z / length;
      for (let d = 0; d < 3; ++d) outPositions[3 * i + d] = positions[3 * v + d];
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(outPositions, 3));
    g.setAttribute('normal', new THREE.BufferAttribute(outNormals, 3));
    return g;
  }

  // shared meshes (corners in whole meshUnits), each made into a geometry once, on first use
  const sharedGeometries = [];
  function sharedGeometry(index) {
    if (!sharedGeometries[index]) {
      const mesh = plan.meshes[index];
      sharedGeometries[index] = creasedGeometry(mesh.vertices.map(v => v * plan.meshUnit), mesh.triangles);
    }
    return sharedGeometries[index];
  }

  function geometryOf(solid) {
    switch (solid.kind) {
      case 'box':
        return new THREE.BoxBufferGeometry(solid.size[0], solid.size[1], solid.size[2]);
      case 'cylinder': {
        const g = new THREE.CylinderBufferGeometry(solid.radius, solid.radius, solid.length, 32);
        g.rotateX(Math.PI / 2);  // three.js cylinders stand along y, ours along z
        return g;
      }
      case 'sphere':
        return new THREE.SphereBufferGeometry(solid.radius, 32, 16);
      case 'mesh':
        return solid.mesh !== undefined ? sharedGeometry(solid.mesh)
                                        : creasedGeometry(solid.vertices, solid.triangles);
    }
    throw new Error('unknown solid kind ' + solid.kind);
  }

  function setPose(object, pose) {
    object.position.set(pose[0], pose[1], pose[2]);
    object.quaternion.set(pose[3], pose[4], pose[5], pose[6]);
  }

  // one material per colour and opacity, one outline per geometry
  const materials = new Map(), outlines = new Map();
  function materialOf(colour, opacity) {
    const key = colour + ' ' + opacity;
    if (!materials.has(key))
      materials.set(key, new THREE.MeshLambertMaterial({
        color: colour, transparent: opacity < 1, opacity: opacity, depthWrite: opacity >= 1,
        side: THREE.DoubleSide}));  // meshes need not wind their triangles one way
    return materials.get(key);
  }
  const outlineMaterial = new THREE.LineBasicMaterial({color: 0x222222, transparent: true, opacity: 0.35});
  function outlineOf(geometry) {
    if (!outlines.has(geometry)) outlines.set(geometry, new THREE.EdgesGeometry(geometry, 30));
    return outlines.get(geometry);
  }

  function makeBody(body) {
    const group = new THREE.Group();
    for (const solid of body.solids) {
      const mesh = new THREE.Mesh(geometryOf(solid), materialOf(solid.colour || body.colour, body.opacity));
      setPose(mesh, solid.pose);
      group.add(mesh);
      const g = mesh.geometry, triangles = (g.index ? g.index.count : g.getAttribute('position').count) / 3;
      if (body.opacity < 1 || triangles > MAX_OUTLINED_TRIANGLES) continue;
      const outline = outlineOf(mesh.geometry);
      // a sphere has no sharp edge, and an empty geometry would make the scene's bounds infinite
      if (outline.getAttribute('position').count > 0)
        mesh.add(new THREE.LineSegments(outline, outlineMaterial));
    }
    scene.add(group);
    return group;
  }

  for (const body of plan.fixed) makeBody(body);
  for (const body of plan.goals) makeBody(body);
  const moving = plan.moving.map(makeBody);

  // the tool path (or the robot's track), a line per segment in its primitive's colour
  function line(points, colour, width) {
    const geometry = new THREE.BufferGeometry().setFromPoints(points.map(p => new THREE.Vector3(p[0], p[1], p[2])));
    return new THREE.Line(geometry, new THREE.LineBasicMaterial({color: colour, linewidth: width}));
  }
  for (const segment of plan.segments)
    scene.add(line(plan.toolPath.slice(segment.first, segment.last + 1), segment.colour, 2));
  // trajectories of moving bodies (physics plans)
  for (const track of plan.tracks)
    scene.add(line(plan.frames.map(frame => frame[track.body]), track.colour, 1));

  // camera on the scene's bounds
  const bounds = new THREE.Box3().setFromObject(scene);
  const centre = bounds.getCenter(new THREE.Vector3());
  const radius = Math.max(bounds.getSize(new THREE.Vector3()).length() / 2, 0.5);
  const camera = new THREE.PerspectiveCamera(40, 1, radius / 100, radius * 20);
  // from the south, steep enough that tall obstacles hide little of the floor
  camera.position.set(centre.x + 0.5 * radius, centre.y - 1.3 * radius, centre.z + 2.2 * radius);
  // "#zoom=F" in the address starts F times closer
  const zoom = Number(new URLSearchParams(window.location.hash.slice(1)).get('zoom'));
  if (zoom > 0) camera.position.sub(centre).divideScalar(zoom).add(centre);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  controls.update();

  // --- the timeline ---------------------------------------------------------------------------------
  const frameCount = plan.frames.length;
  const slider = document.getElementById('timeline');
  slider.max = Math.max(frameCount - 1, 0);
  const playButton = document.getElementById('play');
  const speedSelect = document.getElementById('speed');
  const status = document.getElementById('status');
  const switches = plan.segments.map(s => s.first);  // frames where a new primitive starts
  let frame = 0;
  let playing = frameCount > 1;

  function segmentAt(k) {
    let current = null;
    for (const segment of plan.segments)
      if (segment.first <= k) current = segment;
    return current;
  }

  function show(k) {
    frame = Math.min(Math.max(k, 0), Math.max(frameCount - 1, 0));
    const index = Math.floor(frame);
    if (frameCount > 0)
      for (let b = 0; b < moving.length; ++b) setPose(moving[b], plan.frames[index][b]);
    slider.value = index;
    const segment = segmentAt(index);
    const seconds = (index * plan.frameStep).toFixed(1);
    status.textContent = (segment ? segment.label : 'start') + ' — ' + seconds + ' s of ' +
                         (Math.max(frameCount - 1, 0) * plan.frameStep).toFixed(1) + ' s';
  }

  function setPlaying(on) {
    playing = on && frameCount > 1;
    playButton.textContent = playing ? 'pause' : 'play';
  }

  playButton.addEventListener('click', () => {
    if (!playing && frame >= frameCount - 1) show(0);
    setPlaying(!playing);
  });
  slider.addEventListener('input', () => { setPlaying(false); show(Number(slider.value)); });
  document.getElementById('previous').addEventListener('click', () => {
    setPlaying(false);
    const earlier = switches.filter(f => f < Math.floor(frame));
    show(earlier.length ? earlier[earlier.length - 1] : 0);
  });
  document.getElementById('next').addEventListener('click', () => {
    setPlaying(false);
    const later = switches.find(f => f > Math.floor(frame));
    show(later !== undefined ? later : frameCount - 1);
  });

  function resize() {
    const width = view.clientWidth, height = view.clientHeight;
    renderer.setSize(width, height);
    camera.aspect = width / Math.max(height, 1);
    camera.updateProjectionMatrix();
  }
  window.addEventListener('resize', resize);
  resize();

  // the hash: "#at=F" starts at fraction F of the timeline, "paused" stops there
  const hash = new URLSearchParams(window.location.hash.slice(1));
  if (hash.has('at')) show(Number(hash.get('at')) * Math.max(frameCount - 1, 0));
  else show(0);
  setPlaying(!hash.has('paused'));
  renderer.render(scene, camera);  // the first picture at once, not only at the next animation frame

  let last = null;
  function animate(time) {
    if (last !== null && playing) {
      const next = frame + (time - last) / 1000 * Number(speedSelect.value) / plan.frameStep;
      if (next >= frameCount - 1) { show(frameCount - 1); setPlaying(false); } else show(next);
    }
    last = time;
    controls.update();
    renderer.render(scene, camera);
    document.body.dataset.ready = '1';
    requestAnimationFrame(animate);
  }
  requestAnimationFrame(animate);
})();
