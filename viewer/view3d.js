// The replay viewer's 3D view (docs/viewer.md): the hull surface in the ship frame coloured by the
// map M at the replay time, the UAVs at their stand-off positions with their footprints, their
// recent paths and the no-fly positions; orbit and zoom with three.js's OrbitControls. three.js
// comes inlined in the page as the global THREE_VIEW (cmake/EmbedViewer.cmake), only for traces
// whose hull was imported from a mesh (the trace's ship_frame: one side, or the unrolled hull).
'use strict';

(function (hv) {
  const {cellColor, uavColor, SEAM_MARK} = hv.palette;
  const PATH_LENGTH = 40; // steps of recent path behind each UAV, as in the 2D view
  const FOOTPRINT_COLOR = [40, 120, 255];
  const NO_FLY_COLOR = [17, 17, 17];
  const BACKGROUND = [245, 246, 248];
  const LABEL_SIZE = [40, 26]; // a UAV's number, screen pixels
  const LABEL_LIFT = 0.6; // gap between a UAV and its label, in label heights

  // Per cell of the grid: its 3D surface point, outward normal, the unit direction in which the
  // UAVs stand off from it, and the unit directions of the grid's x (along) and y (up) on the
  // surface, in the ship frame (X stern → bow, Y to port, Z up), in metres. Everything the 3D view
  // draws is placed from these. For a side-plane grid (SPEC §9): X = X0 + (x + ½)·cell,
  // Z = Z0 + (y + ½)·cell, the surface at Y = Ys ∓ depth and the stand-off along ∓Y (− for
  // starboard, + for port), x along +X. An unrolled hull (side "both", docs/hulls.md) carries its
  // surface points; the UAVs stand off along the normal and x runs along the horizontal tangent
  // n × Z (toward the bow on port, away from it on starboard).
  function cellPoints3d(trace) {
    const W = trace.grid.width;
    const H = trace.grid.height;
    const cell = trace.grid.cell_size_m || 1;
    const frame = trace.ship_frame;
    const [x0, z0] = frame.origin;
    const unrolled = frame.side === 'both';
    const sign = frame.side === 'port' ? 1 : -1;
    const point = new Float32Array(W * H * 3);
    const normal = new Float32Array(W * H * 3);
    const standoff = new Float32Array(W * H * 3);
    const along = new Float32Array(W * H * 3);
    const up = new Float32Array(W * H * 3);
    for (let y = 0; y < H; ++y) {
      for (let x = 0; x < W; ++x) {
        const i = y * W + x;
        const n = frame.normal[y][x];
        normal.set(n, 3 * i);
        up.set([0, 0, 1], 3 * i);
        if (unrolled) {
          point.set(frame.surface[y][x], 3 * i);
          standoff.set(n, 3 * i);
          const h = Math.hypot(n[0], n[1]);
          along.set(h > 1e-6 ? [n[1] / h, -n[0] / h, 0] : [1, 0, 0], 3 * i);
          continue;
        }
        point[3 * i] = x0 + (x + 0.5) * cell;
        point[3 * i + 1] = frame.side_plane_y + sign * frame.depth[y][x];
        point[3 * i + 2] = z0 + (y + 0.5) * cell;
        standoff.set([0, sign, 0], 3 * i);
        along.set([1, 0, 0], 3 * i);
      }
    }
    return {W, H, cell, point, normal, standoff, along, up, unrolled};
  }

  // ζ_z in metres: the stand-off of plane z (SPEC §9), from the footprint and the camera aperture.
  function standoffMetres(trace, z) {
    const theta = ((trace.camera && trace.camera.theta_deg) || 90) * Math.PI / 180;
    return trace.footprint[z - 1] * (trace.grid.cell_size_m || 1) / (2 * Math.tan(theta / 2));
  }

  class View3d {
    // Whether the page can show `replay` in 3D; else the reason, for the toggle's tooltip.
    static unavailableReason(replay) {
      if (!replay.trace.ship_frame) {
        return '3D needs a hull imported from a mesh (hullinspect hull import); this trace\'s hull is a mask';
      }
      if (typeof THREE_VIEW === 'undefined') return 'this page was written without three.js';
      return null;
    }

    constructor(replay, container, show) {
      const T = THREE_VIEW;
      this.replay = replay;
      this.show = show;
      this.container = container;
      this.geo = cellPoints3d(replay.trace);
      this.isHull = Uint8Array.from(replay.map, (v) => (v >= 0 ? 1 : 0)); // the same at every t
      this.zeta = [0, standoffMetres(replay.trace, 1), standoffMetres(replay.trace, 2)];
      this.renderer = new T.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
      // Colours reach the screen as given, so the palette's values can be checked in pixels.
      this.renderer.outputColorSpace = 'srgb-linear';
      this.renderer.setClearColor(new T.Color(...BACKGROUND.map((v) => v / 255)), 1);
      container.appendChild(this.renderer.domElement);
      this.scene = new T.Scene();
      this.camera = new T.PerspectiveCamera(40, 1, 0.1, 1e5);
      this.camera.up.set(0, 0, 1);
      this.buildHull();
      this.buildOverlays();
      this.frameCamera();
      this.controls = new T.OrbitControls(this.camera, this.renderer.domElement);
      this.controls.target.copy(this.center);
      this.controls.addEventListener('change', () => this.render());
      this.controls.update();
    }

    // Corner (cx, cy) of the cell lattice (0 ≤ cx ≤ W, 0 ≤ cy ≤ H) on the surface: the mean of the
    // hull cells around it, shifted half a cell towards the corner, so neighbouring tiles meet.
    corner(cx, cy, out) {
      const {W, H, cell, point, along, up} = this.geo;
      let n = 0;
      out[0] = out[1] = out[2] = 0;
      for (const [x, y] of [[cx - 1, cy - 1], [cx, cy - 1], [cx - 1, cy], [cx, cy]]) {
        if (x < 0 || y < 0 || x >= W || y >= H || !this.isHull[y * W + x]) continue;
        const i = 3 * (y * W + x);
        for (let d = 0; d < 3; ++d) {
          out[d] += point[i + d] + ((cx - x - 0.5) * along[i + d] + (cy - y - 0.5) * up[i + d]) * cell;
        }
        ++n;
      }
      out[0] /= n; out[1] /= n; out[2] /= n;
    }

    // One flat-coloured quad (two triangles) per hull cell, corners shared with its neighbours.
    buildHull() {
      const T = THREE_VIEW;
      const {W, H} = this.geo;
      this.hullCells = [];
      for (let i = 0; i < W * H; ++i) if (this.isHull[i]) this.hullCells.push(i);
      const n = this.hullCells.length;
      const pos = new Float32Array(n * 18);
      const c = [[], [], [], []].map(() => new Float32Array(3));
      const box = new T.Box3();
      this.hullCells.forEach((i, k) => {
        const x = i % W;
        const y = Math.floor(i / W);
        this.corner(x, y, c[0]);
        this.corner(x + 1, y, c[1]);
        this.corner(x + 1, y + 1, c[2]);
        this.corner(x, y + 1, c[3]);
        [0, 1, 2, 0, 2, 3].forEach((v, j) => pos.set(c[v], k * 18 + j * 3));
        box.expandByPoint(new T.Vector3(...c[0]));
        box.expandByPoint(new T.Vector3(...c[2]));
      });
      this.box = box;
      this.hullPos = pos;
      this.quadOf = new Int32Array(W * H).fill(-1); // cell → its quad in hullPos
      this.hullCells.forEach((i, k) => { this.quadOf[i] = k; });
      const g = new T.BufferGeometry();
      g.setAttribute('position', new T.BufferAttribute(pos, 3));
      this.hullColors = new Float32Array(n * 18);
      g.setAttribute('color', new T.BufferAttribute(this.hullColors, 3));
      this.hullMesh = new T.Mesh(g, new T.MeshBasicMaterial({vertexColors: true, side: T.DoubleSide}));
      this.scene.add(this.hullMesh);
    }

    // A point `lift` metres out from cell i's surface along its stand-off direction.
    lifted(i, lift, out, at = 0) {
      const {point, standoff} = this.geo;
      for (let d = 0; d < 3; ++d) out[at + d] = point[3 * i + d] + lift * standoff[3 * i + d];
    }

    buildOverlays() {
      const T = THREE_VIEW;
      const {W, H, cell} = this.geo;
      const k = this.replay.uavCount;
      // Footprints: up to s2² copies of the hull's quads per UAV, drawn over the surface.
      const s2 = this.replay.trace.footprint[1];
      this.footprintPos = new Float32Array(k * s2 * s2 * 18);
      const fg = new T.BufferGeometry();
      fg.setAttribute('position', new T.BufferAttribute(this.footprintPos, 3));
      this.footprints = new T.Mesh(fg, new T.MeshBasicMaterial({
        color: new T.Color(...FOOTPRINT_COLOR.map((v) => v / 255)), transparent: true, opacity: 0.35,
        side: T.DoubleSide, depthWrite: false, polygonOffset: true, polygonOffsetFactor: -2,
        polygonOffsetUnits: -4}));
      this.scene.add(this.footprints);
      // No-fly positions: dark translucent tiles at the close-up stand-off.
      if (this.replay.noFly) {
        const cells = [];
        for (let i = 0; i < W * H; ++i) if (this.replay.noFly[i]) cells.push(i);
        const pos = new Float32Array(cells.length * 18);
        cells.forEach((i, j) => this.tile(i, this.zeta[1], pos, j * 18));
        const g = new T.BufferGeometry();
        g.setAttribute('position', new T.BufferAttribute(pos, 3));
        this.noFly = new T.Mesh(g, new T.MeshBasicMaterial({
          color: new T.Color(...NO_FLY_COLOR.map((v) => v / 255)), transparent: true, opacity: 0.45,
          side: T.DoubleSide, depthWrite: false}));
        this.scene.add(this.noFly);
      }
      // The seam of a grid that closes on itself: the line where column 0 meets column W − 1, through
      // the midpoint of each row's two ends (grid positions have surface points, hull or not), a
      // little out along their mean normal so the tiles do not hide it.
      this.seamPoints = [];
      if (this.replay.trace.ship_frame.seam) {
        const {point, normal} = this.geo;
        for (let y = 0; y < H; ++y) {
          const a = 3 * y * W;
          const b = 3 * (y * W + W - 1);
          const n = [0, 1, 2].map((d) => normal[a + d] + normal[b + d]);
          const length = Math.hypot(...n) || 1;
          this.seamPoints.push([0, 1, 2].map((d) =>
            (point[a + d] + point[b + d]) / 2 + (0.1 * cell * n[d]) / length));
        }
        const g = new T.BufferGeometry();
        g.setAttribute('position', new T.BufferAttribute(Float32Array.from(this.seamPoints.flat()), 3));
        this.seam = new T.Line(g, new T.LineBasicMaterial({
          color: new T.Color().setStyle(SEAM_MARK, 'srgb-linear')}));
        this.scene.add(this.seam);
      }
      // UAVs: a sphere each, a line down to the cell it looks at, and its recent path.
      const radius = Math.max(0.45 * cell, 0.006 * this.box.getSize(new T.Vector3()).length());
      const sphere = new T.SphereGeometry(radius, 16, 12);
      this.uavs = [];
      this.failedColor = new T.Color(0.6, 0.6, 0.6); // a failed UAV is grey, as in the 2D view
      for (let u = 0; u < k; ++u) {
        // CSS colours as they are: the renderer outputs linear values unchanged (see constructor).
        const color = new T.Color().setStyle(uavColor(u), 'srgb-linear');
        const mesh = new T.Mesh(sphere, new T.MeshBasicMaterial({color}));
        const sight = new T.Line(new T.BufferGeometry(), new T.LineBasicMaterial({color}));
        sight.geometry.setAttribute('position', new T.BufferAttribute(new Float32Array(6), 3));
        const path = new T.Line(new T.BufferGeometry(), new T.LineBasicMaterial({color}));
        path.geometry.setAttribute('position',
                                   new T.BufferAttribute(new Float32Array((PATH_LENGTH + 1) * 3), 3));
        const label = this.label(String(u), uavColor(u));
        this.scene.add(mesh, sight, path, label);
        this.uavs.push({mesh, sight, path, label, color});
      }
    }

    // The UAV's number, drawn above its sphere at the same size on screen whatever the zoom.
    label(text, color) {
      const T = THREE_VIEW;
      const canvas = document.createElement('canvas');
      const [w, h] = LABEL_SIZE;
      [canvas.width, canvas.height] = [w, h];
      const ctx = canvas.getContext('2d');
      ctx.fillStyle = 'rgba(255, 255, 255, 0.85)';
      ctx.fillRect(0, 0, w, h);
      ctx.strokeStyle = color;
      ctx.lineWidth = 3;
      ctx.strokeRect(1.5, 1.5, w - 3, h - 3);
      ctx.fillStyle = color;
      ctx.font = `bold ${Math.round(0.7 * h)}px sans-serif`;
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      ctx.fillText(text, w / 2, h / 2 + 1);
      const texture = new T.CanvasTexture(canvas);
      texture.colorSpace = 'srgb-linear';
      const sprite = new T.Sprite(new T.SpriteMaterial({map: texture, sizeAttenuation: false, depthTest: false}));
      sprite.renderOrder = 1;
      return sprite;
    }

    // A cell-sized square tile at cell i, `lift` metres out from its surface, into pos[at...].
    tile(i, lift, pos, at) {
      const {cell, along, up} = this.geo;
      const p = new Float32Array(3);
      this.lifted(i, lift, p);
      const h = cell / 2;
      const corners = [[-h, -h], [h, -h], [h, h], [-h, h]];
      [0, 1, 2, 0, 2, 3].forEach((v, j) => {
        for (let d = 0; d < 3; ++d) {
          pos[at + j * 3 + d] = p[d] + corners[v][0] * along[3 * i + d] + corners[v][1] * up[3 * i + d];
        }
      });
    }

    // The camera looks at the inspected side from outside and a little from the bow and above,
    // as far as the whole hull needs to fill the view's width (called again on resizing); an
    // unrolled hull is seen from starboard, ahead and higher up, so that the bow and the deck
    // line of the far side show too.
    frameCamera() {
      const T = THREE_VIEW;
      this.center = this.box.getCenter(new T.Vector3());
      const size = this.box.getSize(new T.Vector3());
      const sign = this.replay.trace.ship_frame.side === 'port' ? 1 : -1;
      const halfWidth = Math.atan(Math.tan((this.camera.fov * Math.PI) / 360) * this.camera.aspect);
      const d = Math.max((0.66 * size.x) / Math.tan(halfWidth), (0.8 * size.z) /
                         Math.tan((this.camera.fov * Math.PI) / 360));
      const dir = this.geo.unrolled ? new T.Vector3(0.45, -1, 0.7).normalize()
                                    : new T.Vector3(0.2, sign, 0.25).normalize();
      this.camera.position.copy(this.center).addScaledVector(dir, d);
      this.camera.lookAt(this.center);
    }

    resize(width, height) {
      this.renderer.setPixelRatio(window.devicePixelRatio || 1);
      this.renderer.setSize(width, height);
      this.camera.aspect = width / height;
      this.camera.updateProjectionMatrix();
      if (!this.framed) {
        this.frameCamera();
        if (this.controls) this.controls.update();
        this.framed = true;
      }
      // Labels of LABEL_SIZE screen pixels: a sprite without size attenuation of scale s covers
      // s / (2·tan(fov/2)) of the view's height.
      const k = (2 * Math.tan((this.camera.fov * Math.PI) / 360)) / height;
      for (const u of this.uavs) u.label.scale.set(LABEL_SIZE[0] * k, LABEL_SIZE[1] * k, 1);
    }

    // Everything that changes with the replay time, then one render.
    draw() {
      const r = this.replay;
      const t = r.t;
      this.hullCells.forEach((i, k) => {
        const c = cellColor(r, i, this.show.regions);
        for (let v = 0; v < 6; ++v) {
          this.hullColors[k * 18 + v * 3] = c[0] / 255;
          this.hullColors[k * 18 + v * 3 + 1] = c[1] / 255;
          this.hullColors[k * 18 + v * 3 + 2] = c[2] / 255;
        }
      });
      this.hullMesh.geometry.attributes.color.needsUpdate = true;
      const {W, H} = this.geo;
      const fp = r.trace.footprint;
      let tiles = 0;
      for (let k = 0; k < r.uavCount; ++k) {
        const s = r.uavState(t, k);
        const i = s.y * W + s.x;
        const u = this.uavs[k];
        const p = new Float32Array(3);
        this.lifted(i, this.zeta[s.z], p);
        u.mesh.position.set(p[0], p[1], p[2]);
        u.label.position.set(p[0], p[1], p[2]);
        // On the ground or away at its launch site (flying out or home): not on the hull.
        const offHull = !s.airborne || s.away > 0;
        u.mesh.visible = !offHull;
        u.label.visible = this.show.labels && !offHull;
        u.mesh.material.color.copy(s.active ? u.color : this.failedColor);
        const sight = u.sight.geometry.attributes.position;
        sight.array.set(p, 0);
        this.lifted(i, 0, sight.array, 3);
        sight.needsUpdate = true;
        u.sight.visible = s.active && s.transit === 0 && !offHull;
        const path = u.path.geometry.attributes.position;
        const first = Math.max(0, t - PATH_LENGTH);
        for (let j = first; j <= t; ++j) {
          const q = r.uavState(j, k);
          this.lifted(q.y * W + q.x, this.zeta[q.z], path.array, (j - first) * 3);
        }
        path.needsUpdate = true;
        u.path.geometry.setDrawRange(0, t - first + 1);
        u.path.visible = this.show.paths;
        if (!this.show.footprints || !s.active || s.transit > 0 || offHull) continue;
        const half = (fp[s.z - 1] - 1) / 2;
        for (let y = Math.max(0, s.y - half); y <= Math.min(H - 1, s.y + half); ++y) {
          for (let x = Math.max(0, s.x - half); x <= Math.min(W - 1, s.x + half); ++x) {
            const q = this.quadOf[y * W + x];
            if (q < 0) continue;
            this.footprintPos.set(this.hullPos.subarray(q * 18, q * 18 + 18), tiles * 18);
            ++tiles;
          }
        }
      }
      this.footprints.geometry.attributes.position.needsUpdate = true;
      this.footprints.geometry.setDrawRange(0, tiles * 6);
      this.render();
    }

    // Labels of UAVs close together on screen are stacked upwards so none covers another:
    // left to right, each goes on the lowest row where it overlaps no label placed before.
    // labelBoxes keeps the boxes (canvas pixels) for the browser test.
    placeLabels() {
      const T = THREE_VIEW;
      const canvas = this.renderer.domElement;
      const width = canvas.clientWidth;
      const height = canvas.clientHeight;
      const [w, h, gap] = [LABEL_SIZE[0], LABEL_SIZE[1], 2];
      const anchors = [];
      this.uavs.forEach((u, k) => {
        if (!u.label.visible) return;
        const q = new T.Vector3().copy(u.mesh.position).project(this.camera);
        anchors.push({k, x: ((q.x + 1) / 2) * width, y: ((1 - q.y) / 2) * height});
      });
      anchors.sort((a, b) => a.x - b.x || a.k - b.k);
      this.labelBoxes = [];
      for (const a of anchors) {
        let row = 0;
        const box = (r) => ({k: a.k, x: a.x - w / 2, y: a.y - LABEL_LIFT * h - r * (h + gap) - h, w, h});
        const clash = (b) => this.labelBoxes.some((o) => b.x < o.x + o.w && o.x < b.x + b.w &&
                                                           b.y < o.y + o.h && o.y < b.y + b.h);
        while (clash(box(row))) ++row;
        this.uavs[a.k].label.center.set(0.5, -LABEL_LIFT - row * (1 + gap / h));
        this.labelBoxes.push(box(row));
      }
    }

    render() {
      this.placeLabels();
      this.renderer.render(this.scene, this.camera);
    }
  }

  hv.View3d = View3d;
  hv.cellPoints3d = cellPoints3d;
})(window.hullinspectViewer = window.hullinspectViewer || {});
