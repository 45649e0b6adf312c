// ncurve's 3D backplot: the moves of a run as GPU line segments (backplot-lines.js), orbit / pan /
// zoom, standard views, axes with ticks (backplot-axes.js), hover and click on a move. Used by the
// page of `ncurve run --html` (run.js) and meant for any other page: it needs three.js,
// OrbitControls (Debian's libjs-three, release 111), backplot-decode.js, backplot-geometry.js,
// backplot-lines.js, backplot-axes.js, backplot-holes.js and backplot-measure.js loaded first, backplot-part.js for setPart,
// backplot-programmed.js for moves.programmed and backplot-cutter.js for setCutter.
//
//   const moves = NcurveBackplot.decode(data);        // the JSON of `run --html` (docs/html.md)
//   const plot = NcurveBackplot.create(container, moves, {onHover(i) {}, onClick(i) {}});
//   plot.setView('iso'); plot.highlight([3, 4]); plot.setColors(i => [255, 0, 0]); plot.setTool([x, y, z]); plot.state();
//   plot.setReference([x0, y0, z0, x1, y1, z1, ...]);  // a curve in grey under the moves
//   plot.setPart(NcurveBackplot.decodePart(data.part));   // the cut part, shaded, under the moves
//   options.frame: another box the views fit too ({lo, hi, frameLo, frameHi}, backplot-geometry.js);
//   plot.addLayer(object3D) draws it with the moves (freed with them), plot.toWorld(p) places it
//   plot.measure.set(true);  // the Measure tool (backplot-measure.js); options.measureWhere(i) names a move
//   plot.showProgrammed(false);  // moves.programmed: the programmed contour beside a compensated path
//   plot.setCutter({centre: [x, y, z], radius: 5, plane: 17, height: 15});  // the tool drawn at a point
//
// moves: {count, kind: Uint8Array (0 rapid, 1 feed, 2 arc), start, end: Float32/64Array (X Y Z of
// each move, X as a radius on a lathe), arcIndex: Int32Array (per move, its arc or -1), arcs:
// Float32Array (per arc: centre X Y Z, sweep in radians counter-clockwise, plane 17/18/19),
// rapidCorners: Map (a dog-leg rapid's number -> its corners' X Y Z in order; none: a straight rapid),
// block: Uint32Array (per move, its block), lathe, diameter, inch, plane, alarmAt: [X, Y, Z] | null,
// rotary: [{axis, unit, min, max}] (the A, B, C axes the run moved, not drawn), rotaryEnd:
// Float64Array (per rotary axis in turn, its end for each move), programmed (optional: the programmed
// contour, as backplot-programmed.js takes it)}.
(function (global) {
  'use strict';
  const THREE = global.THREE;
  const {KIND_NAMES, KIND_COLORS} = global.NcurveBackplotLines;
  const HIGHLIGHT = 0xd81b60;
  const REFERENCE = 0x8f979f;  // setReference's curve

  function create(container, moves, options) {
    options = options || {};
    const n = moves.count;
    const worldUp = moves.lathe ? new THREE.Vector3(0, 1, 0) : new THREE.Vector3(0, 0, 1);
    const G = global.NcurveBackplotGeometry.build(moves, options.frame);
    const {lo, hi, diag, origin, perm, toWorld, segOf, first, counts, moveCounts, total, layers} = G;

    // the moves' lines, their colours and picking (backplot-lines.js)
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xfcfcfd);
    const lines = global.NcurveBackplotLines.create({scene, moves, geometry: G});

    let reference = null;  // setReference's line
    const programmed = global.NcurveBackplotProgrammed
      ? global.NcurveBackplotProgrammed.create(scene, moves.programmed, G, !!moves.lathe) : null;
    const cutter = global.NcurveBackplotCutter ? global.NcurveBackplotCutter.create(scene, toWorld) : null;
    let part = null;  // setPart's mesh, and its lights
    const partLights = [new THREE.AmbientLight(0xffffff, 0.55), new THREE.DirectionalLight(0xffffff, 0.55)];
    // the highlighted moves, drawn over the rest
    const hlGeometry = new THREE.BufferGeometry();
    const hlLines = new THREE.LineSegments(hlGeometry,
      new THREE.LineBasicMaterial({color: HIGHLIGHT, depthTest: false, transparent: true}));
    hlLines.renderOrder = 10;
    hlLines.frustumCulled = false;
    scene.add(hlLines);
    const hoverGeometry = new THREE.BufferGeometry();
    const hoverLines = new THREE.LineSegments(hoverGeometry,
      new THREE.LineBasicMaterial({color: 0x000000, depthTest: false, transparent: true}));
    hoverLines.renderOrder = 11;
    hoverLines.frustumCulled = false;
    scene.add(hoverLines);
    const segmentsOf = (list) => {
      let c = 0;
      for (const i of list) if (i >= 0 && i < n) c += segOf[i];
      const out = new Float32Array(6 * c);
      let o = 0;
      for (const i of list) {
        if (!(i >= 0 && i < n)) continue;
        const src = layers[moves.kind[i]].pos;
        out.set(src.subarray(6 * first[i], 6 * (first[i] + segOf[i])), o);
        o += 6 * segOf[i];
      }
      return new THREE.BufferAttribute(out, 3);
    };

    // the grid, the axes and their labels over the canvas (backplot-axes.js); the overlay is put over
    // the canvas once that is in place
    const overlay = document.createElement('div');
    overlay.className = 'ncurve-overlay';
    const axes = global.NcurveBackplotAxes.create({scene, overlay, container, moves, geometry: G, alarmLabel: options.alarmLabel});
    const wlo = axes.lo, whi = axes.hi, pad = axes.pad;

    // renderer, camera, controls
    // (a renderer handed on by the plot before keeps its context and compiled shaders); no
    // antialiasing for a big path, which would take twice as long to draw without a GPU
    const antialias = total <= 500000;
    let renderer = options.renderer;
    if (renderer && renderer.getContext().getContextAttributes().antialias !== antialias) {
      renderer.dispose();
      renderer.forceContextLoss();
      renderer.domElement.remove();
      renderer = null;
    }
    if (!renderer) renderer = new THREE.WebGLRenderer({antialias, preserveDrawingBuffer: true});
    renderer.setPixelRatio(global.devicePixelRatio || 1);
    if (renderer.domElement.parentNode !== container) container.appendChild(renderer.domElement);
    renderer.domElement.className = 'ncurve-canvas';
    const listeners = [];
    const listen = (target, type, fn) => { target.addEventListener(type, fn); listeners.push([target, type, fn]); };
    container.appendChild(overlay);
    const radius = diag / 2;
    const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 8 * radius + 1);
    camera.up.copy(worldUp);
    const controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.screenSpacePanning = true;
    controls.enableKeys = false;
    // the wheel zooms about the point under the pointer, a fifth a notch
    controls.enableZoom = false;
    listen(renderer.domElement, 'wheel', (e) => {
      e.preventDefault();
      const notches = e.deltaY / (e.deltaMode === 1 ? 3 : e.deltaMode === 2 ? 0.1 : 100);
      const r = renderer.domElement.getBoundingClientRect();
      const at = new THREE.Vector3((e.clientX - r.left) / r.width * 2 - 1, 1 - (e.clientY - r.top) / r.height * 2, 0);
      const before = at.clone().unproject(camera);
      camera.zoom = Math.min(Math.max(camera.zoom * Math.pow(1.2, -Math.max(-5, Math.min(5, notches))), 1e-4), 1e7);
      camera.updateProjectionMatrix();
      const shift = before.sub(at.unproject(camera));
      camera.position.add(shift);
      controls.target.add(shift);
      controls.update();
      requestRender();
    });
    let viewName = '', lastView = '', settingView = false;
    const resize = () => {
      const w = Math.max(container.clientWidth, 1), h = Math.max(container.clientHeight, 1);
      renderer.setSize(w, h, false);
      renderer.domElement.style.width = w + 'px';
      renderer.domElement.style.height = h + 'px';
      const half = radius * 1.25, aspect = w / h;
      camera.left = -half * Math.max(aspect, 1), camera.right = half * Math.max(aspect, 1);
      camera.top = half / Math.min(aspect, 1), camera.bottom = -half / Math.min(aspect, 1);
      camera.updateProjectionMatrix();
      requestRender();
    };
    // the views: where the camera looks from (world), machine-wise
    const VIEWS = moves.lathe
      ? {zx: [0, 0, 1], top: [0, 1, 1e-4], end: [1, 0, 0], iso: [1, 0.8, 1.2]}
      : {top: [0, -1e-4, 1], front: [0, -1, 0], side: [1, 0, 0], iso: [1, -1, 1]};
    // a view fits the cuts (the axes' box); `all`: every move, rapids to and from home included
    const glo = toWorld(lo, [0, 0, 0]), ghi = toWorld(hi, [0, 0, 0]);
    const setView = (name, all = false) => {
      const d = VIEWS[name];
      if (!d) return false;
      viewName = name;
      const flo = all ? glo.map((v, k) => Math.min(v, wlo[k] - pad)) : wlo.map((v) => v - pad);
      const fhi = all ? ghi.map((v, k) => Math.max(v, whi[k])) : whi;
      const dir = new THREE.Vector3(d[0], d[1], d[2]).normalize();
      // the box's corners as seen from there: the camera centred on them, zoomed to fit
      controls.target.set(0, 0, 0);
      camera.position.copy(dir.clone().multiplyScalar(4 * radius + 1));
      camera.lookAt(controls.target);
      camera.updateMatrixWorld();
      const inv = new THREE.Matrix4().getInverse(camera.matrixWorld);
      const b = new THREE.Box3();
      for (const x of [flo[0], fhi[0]]) for (const y of [flo[1], fhi[1]]) for (const z of [flo[2], fhi[2]])
        b.expandByPoint(new THREE.Vector3(x, y, z).applyMatrix4(inv));
      const centre = new THREE.Vector3((b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, 0).applyMatrix4(camera.matrixWorld);
      const shift = centre.sub(camera.position);  // in the view's plane
      controls.target.copy(shift);
      camera.position.add(shift);
      const w = Math.max(b.max.x - b.min.x, diag * 1e-3), h = Math.max(b.max.y - b.min.y, diag * 1e-3);
      // room for the labels round the drawing, the buttons above and the legend below
      const H = Math.max(renderer.domElement.clientHeight, 1), above = 70, below = 100;
      const cw = Math.max(renderer.domElement.clientWidth - 170, 50), ch = Math.max(H - above - below, 50);
      const ppu = Math.min(cw / w, ch / h);  // pixels per world unit
      camera.zoom = ppu * (camera.top - camera.bottom) / H;
      camera.updateProjectionMatrix();
      const upWorld = new THREE.Vector3(0, 1, 0).applyQuaternion(camera.quaternion).multiplyScalar((below - above) / 2 / ppu);
      controls.target.sub(upWorld);
      camera.position.sub(upWorld);
      settingView = true;
      controls.update();
      settingView = false;
      viewName = lastView = name;
      requestRender();
      return true;
    };

    const v3 = new THREE.Vector3();
    const project = (w) => {
      v3.copy(w).project(camera);
      const c = renderer.domElement;
      return [(v3.x + 1) / 2 * c.clientWidth, (1 - v3.y) / 2 * c.clientHeight];
    };
    const look = new THREE.Vector3();
    const placeLabels = () => {
      camera.getWorldDirection(look);
      const along = Math.max(Math.abs(look.x), Math.abs(look.y), Math.abs(look.z)) > 0.999;
      axes.place(project, renderer.domElement.clientWidth, renderer.domElement.clientHeight, along);
    };
    // the drilled holes marked (backplot-holes.js); the Measure tool (backplot-measure.js)
    const holes = global.NcurveBackplotHoles.create({scene, moves, geometry: G});
    const measure = global.NcurveBackplotMeasure.create({scene, container, canvas: renderer.domElement, camera, moves, geometry: G,
      where: options.measureWhere || ((i) => `move ${i + 1}`), requestRender});
    if (options.measure) measure.set(true);

    let pending = false;
    function requestRender() {
      if (pending) return;
      pending = true;
      global.requestAnimationFrame(render);
    }
    // a redraw slower than 80 ms while turning: the coarse lines until the pointer is released
    let interacting = false, coarse = false, lastRender = 0;
    const useCoarse = (on) => {
      coarse = on;
      lines.useCoarse(on);
    };
    controls.addEventListener('start', () => { interacting = true; lastRender = 0; });
    controls.addEventListener('end', () => {
      interacting = false;
      if (coarse) useCoarse(false), requestRender();
    });
    // a big path shows its coarse lines first, on a slow GPU long before the full ones are drawn
    let preview = lines.hasCoarse;
    function render() {
      pending = false;
      const now = performance.now();
      if (interacting && lines.hasCoarse && !coarse && lastRender && now - lastRender > 80) useCoarse(true);
      if (preview) useCoarse(true);
      lastRender = now;
      const wpp = (camera.top - camera.bottom) / camera.zoom / Math.max(renderer.domElement.clientHeight, 1);
      lines.dash(wpp);
      if (programmed) programmed.dash(wpp);
      if (part) {  // the light from over the viewer's shoulder
        const sun = partLights[1];
        sun.position.copy(camera.position).addScaledVector(camera.up, diag);
        sun.target.position.copy(controls.target);
        sun.target.updateMatrixWorld();
      }
      // the labels first: they set the tick marks and the grid this frame draws
      camera.updateMatrixWorld();
      placeLabels();
      renderer.setRenderTarget(null);
      renderer.render(scene, camera);
      if (api.onRender) api.onRender();
      if (preview) {
        preview = false;
        setTimeout(() => {
          if (!interacting) useCoarse(false), requestRender();
        }, 0);
      }
    }
    controls.addEventListener('change', () => {
      if (!settingView) viewName = '';  // moved by hand: no named view
      requestRender();
    });

    const pick = (clientX, clientY) => lines.pick(renderer, camera, clientX, clientY);

    let hovered = -1;
    const setHover = (i) => {
      if (i === hovered) return;
      hovered = i;
      hoverGeometry.setAttribute('position', segmentsOf(i >= 0 ? [i] : []));
      requestRender();
      if (api.onHover) api.onHover(i);
    };
    let down = null, lastPointer = null, pickQueued = false;
    const el = renderer.domElement;
    listen(el, 'pointerdown', (e) => { down = [e.clientX, e.clientY]; setHover(-1); });
    listen(el, 'pointerup', (e) => {
      const still = down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) < 4;
      if (still && measure.on) measure.click(e.clientX, e.clientY);
      else if (still && api.onClick) api.onClick(pick(e.clientX, e.clientY));
      down = null;
    });
    listen(el, 'pointermove', (e) => {
      if (e.buttons) return;
      lastPointer = [e.clientX, e.clientY];
      if (pickQueued) return;
      pickQueued = true;
      global.requestAnimationFrame(() => { pickQueued = false; setHover(pick(lastPointer[0], lastPointer[1])); });
    });
    listen(el, 'pointerleave', () => setHover(-1));
    listen(document, 'keydown', (e) => measure.key(e));
    // the container's own size, not the window's: a page around it may grow or shrink it (a header
    // wrapping onto two lines) and a canvas left bigger is cut off at the container's edge
    const sizeWatch = global.ResizeObserver ? new global.ResizeObserver(() => resize()) : null;
    if (sizeWatch) sizeWatch.observe(container);
    else listen(global, 'resize', resize);

    const api = {
      onHover: options.onHover || null,
      onClick: options.onClick || null,
      onRender: null,
      moves, camera, controls, renderer, measure,
      setView, fit: () => setView(viewName || lastView), fitAll: () => setView(viewName || lastView, true),
      views: Object.keys(VIEWS),
      pick,
      // colours: fn(i) -> [r, g, b] (0..255) or null for the kind's colour; no argument: by kind
      setColors(fn) {
        lines.setColors(fn);
        requestRender();
      },
      // a curve drawn thin and grey under the moves (a generated program's curve): points flat, X Y Z
      // each as the moves' (X as a radius on a lathe); null removes it
      setReference(points) {
        if (reference) {
          scene.remove(reference);
          reference.geometry.dispose();
          reference.material.dispose();
          reference = null;
        }
        const count = points ? Math.floor(points.length / 3) : 0;
        if (count >= 2) {
          const pos = new Float32Array(3 * count), p = [0, 0, 0], w = [0, 0, 0];
          for (let i = 0; i < count; i++) {
            p[0] = points[3 * i], p[1] = points[3 * i + 1], p[2] = points[3 * i + 2];
            toWorld(p, w);
            pos[3 * i] = w[0], pos[3 * i + 1] = w[1], pos[3 * i + 2] = w[2];
          }
          const g = new THREE.BufferGeometry();
          g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
          // drawn first and leaving the depth alone: the moves over it cover it
          reference = new THREE.Line(g, new THREE.LineBasicMaterial({color: REFERENCE, depthWrite: false}));
          reference.renderOrder = -1;
          reference.frustumCulled = false;
          scene.add(reference);
        }
        requestRender();
      },
      // a three.js object of another file (backplot-compare.js) in the scene; toWorld: where a point of
      // the machine (X Y Z, X as a radius on a lathe) is in the scene
      addLayer(object) { scene.add(object); requestRender(); },
      toWorld: (p) => toWorld(p, [0, 0, 0]),
      // the cut part (decodePart), shaded under the moves; null removes it
      setPart(p) {
        if (part) {
          scene.remove(part);
          partLights.forEach((l) => scene.remove(l));
          part.geometry.dispose();
          part.material.dispose();
          part = null;
        }
        if (p && (p.lathe ? p.contours.length > 0 : p.nx >= 2 && p.ny >= 2)) {
          part = global.NcurveBackplotPart.mesh(p, toWorld);
          scene.add(part);
          partLights.forEach((l) => scene.add(l));
          // the camera's depth range widened to hold the whole part, which may reach far past the path
          part.geometry.computeBoundingSphere();
          const s = part.geometry.boundingSphere, reach = s.center.length() + s.radius;
          camera.near = -reach - 1;
          camera.far = 8 * radius + 1 + reach;
        } else {
          camera.near = 0;
          camera.far = 8 * radius + 1;
        }
        camera.updateProjectionMatrix();
        requestRender();
      },
      highlight(list) {
        hlGeometry.setAttribute('position', segmentsOf(list || []));
        requestRender();
      },
      hover: setHover,
      // a ring where the tool is (machine X Y Z, X as a radius on a lathe); null hides it
      setTool(p) {
        if (!api.toolLabel) api.toolLabel = axes.marker('tool');
        api.toolLabel.hidden = !p;
        if (p) api.toolLabel.world.fromArray(toWorld(p, [0, 0, 0]));
        requestRender();
      },
      // the programmed contour (moves.programmed) shown or not; its drawn segments' ends, machine X Y Z
      showProgrammed(on) {
        if (programmed) programmed.show(on), requestRender();
      },
      programmedPoints: () => (programmed ? Array.from(programmed.points()) : []),
      // the tool drawn at a point (backplot-cutter.js), null hides it; its circle's points, machine X Y Z
      setCutter(spec) {
        if (cutter) cutter.set(spec), requestRender();
      },
      cutterPoints: () => (cutter ? cutter.points() : []),
      // where move i's middle is on the page (client coordinates)
      screenOf(i) {
        const L = layers[moves.kind[i]], s = first[i] + (segOf[i] >> 1), v = 6 * s;
        const w = segOf[i] === 1
          ? [(L.pos[v] + L.pos[v + 3]) / 2, (L.pos[v + 1] + L.pos[v + 4]) / 2, (L.pos[v + 2] + L.pos[v + 5]) / 2]
          : [L.pos[v], L.pos[v + 1], L.pos[v + 2]];
        const [x, y] = project(new THREE.Vector3(w[0], w[1], w[2]));
        const rect = renderer.domElement.getBoundingClientRect();
        return {x: rect.left + x, y: rect.top + y};
      },
      // where a point of the machine (X Y Z, X as a radius on a lathe) is on the page
      screenOfPoint(p) {
        const [x, y] = project(new THREE.Vector3(...toWorld(p, [0, 0, 0])));
        const rect = renderer.domElement.getBoundingClientRect();
        return {x: rect.left + x, y: rect.top + y};
      },
      render() { pending = false; render(); },
      state() {
        return {
          moveCount: n,
          kinds: {rapid: moveCounts[0], feed: moveCounts[1], arc: moveCounts[2]},
          segments: {rapid: counts[0], feed: counts[1], arc: counts[2]},
          view: viewName, hovered, coarse,
          // on the canvas: each axis's tick marks and numbers shown, and the axis names (centre, size)
          axes: axes.shown(),
          holes: holes.list(),  // the drilled holes marked: machine X Y Z of each hole's top
          reference: reference ? reference.geometry.attributes.position.count : 0,
          programmed: programmed ? {moves: programmed.moves, segments: programmed.segments, visible: programmed.visible} : null,
          cutter: cutter ? cutter.state() : null,
          part: part ? part.geometry.index.count / 3 : 0,
          partDeviation: part ? part.userData.deviated : null,  // {within, gouge, left}: grid points coloured
          camera: {position: camera.position.toArray(), zoom: camera.zoom, target: controls.target.toArray()},
        };
      },
      // keepRenderer: the WebGL renderer (its canvas left in place) is returned for the next plot's
      // options.renderer; otherwise its context is freed too
      dispose(how) {
        const keep = !!(how && how.keepRenderer);
        for (const [target, type, fn] of listeners) target.removeEventListener(type, fn);
        if (sizeWatch) sizeWatch.disconnect();
        controls.dispose();
        // free the GPU buffers and the context now, not at the next garbage collection
        scene.traverse((o) => {
          if (o.geometry) o.geometry.dispose();
          if (o.material) o.material.dispose();
        });
        lines.dispose();
        measure.dispose();
        container.removeChild(overlay);
        if (keep) return renderer;
        renderer.dispose();
        renderer.forceContextLoss();
        container.removeChild(renderer.domElement);
        return null;
      },
    };
    const defaultView = moves.lathe ? 'zx' : moves.plane === 18 ? 'front' : moves.plane === 19 ? 'side' : 'iso';
    resize();
    setView(options.view || defaultView);
    return api;
  }

  global.NcurveBackplot = {decode: global.NcurveBackplotDecode.decode, decodePart: global.NcurveBackplotPart.decode, create,
    KIND_NAMES, KIND_COLORS, DEVIATION_COLOURS: global.NcurveBackplotPart.DEVIATION_COLOURS,
    niceStep: global.NcurveBackplotAxes.niceStep};
})(window);
