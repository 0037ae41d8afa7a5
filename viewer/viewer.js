// hullinspect replay viewer (docs/viewer.md): draws a mission trace (docs/trace-format.md) like the
// paper's Fig. 5 and replays it. Plain browser JavaScript, no dependencies, nothing fetched.
//
// State at time t is rebuilt from keyframes + deltas: the map M is copied every KEYFRAME_INTERVAL
// frames while loading, and a seek restores the nearest keyframe at or before t and applies the
// cell changes of the frames after it (at most KEYFRAME_INTERVAL - 1 of them). Planner annotations
// and layers, which traces record only when they change, are found by binary search.
'use strict';

(function () {
  const KEYFRAME_INTERVAL = 128;
  const PATH_LENGTH = 40; // steps of recent path drawn behind each UAV

  // Cell colours (RGB). docs/viewer.md and the browser test use the same values.
  const COLORS = {
    nonHull: [38, 43, 51],
    unknown: [139, 147, 158],
    clean: [226, 230, 235],
    corrosion: [245, 140, 40],
    inspected: [46, 160, 67],
  };
  // Partition regions: unknown cells in the region's colour, explored cells in a light tint of it.
  // Blues, purples, teals and pinks: far from the orange, green and light red of cell states.
  const REGION_COLORS = [
    [78, 121, 167], [150, 110, 190], [80, 160, 170], [200, 110, 150], [110, 120, 140], [100, 140, 225],
    [170, 90, 140], [60, 140, 130], [160, 150, 220], [70, 170, 200], [180, 130, 170], [90, 90, 170],
  ];
  const REGION_TINT = 0.62; // share of white mixed into a region's colour for explored cells
  // UAV k is drawn in a dark shade of region k's colour.
  const UAV_SHADE = 0.3;
  const FOOTPRINT_FILL = 'rgba(40, 120, 255, 0.22)';
  const LAYER_COLORS = {frontiers: 'rgba(255, 105, 97, 0.62)'};
  const EXTRA_LAYER_COLORS = [
    'rgba(150, 80, 255, 0.45)', 'rgba(0, 190, 220, 0.45)', 'rgba(255, 215, 0, 0.55)',
    'rgba(255, 0, 190, 0.40)', 'rgba(120, 200, 0, 0.45)',
  ];
  const M_NAMES = ['unknown', 'clean (non-corroded, seen)', 'corrosion expected or detected',
    'corrosion inspected'];

  const $ = (id) => document.getElementById(id);
  const rgb = (c) => `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
  const mix = (c, d, w) => c.map((v, i) => Math.round(v * (1 - w) + d[i] * w));

  function regionColor(owner) { return REGION_COLORS[owner % REGION_COLORS.length]; }
  function regionTint(owner) { return mix(regionColor(owner), [255, 255, 255], REGION_TINT); }
  function uavColor(k) { return rgb(mix(regionColor(k), [0, 0, 0], UAV_SHADE)); }
  function layerColor(name, i) {
    return LAYER_COLORS[name] || EXTRA_LAYER_COLORS[i % EXTRA_LAYER_COLORS.length];
  }

  // Last index i with times[i] <= t, or -1.
  function lastAtOrBefore(times, t) {
    let lo = 0;
    let hi = times.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (times[mid] <= t) lo = mid + 1; else hi = mid;
    }
    return lo - 1;
  }

  // ---------------------------------------------------------------------------------------------
  // The replay: everything derived from the trace once, and the state at the current time.
  class Replay {
    constructor(trace) {
      if (!trace || trace.format !== 'hullinspect-trace') throw new Error('not a hullinspect trace');
      if (trace.version !== 1) throw new Error(`trace version ${trace.version} is not supported`);
      this.trace = trace;
      this.W = trace.grid.width;
      this.H = trace.grid.height;
      this.frameCount = trace.frames.length;
      this.lastT = this.frameCount - 1;
      this.uavCount = trace.frames[0].u.length / 5;
      this.truth = this.parseRows(trace.truth);
      this.prior = this.parseRows(trace.prior);
      this.owner = trace.partition ? this.parseRows(trace.partition, true) : null;
      this.indexChanges();
      this.indexUavs();
      this.indexAnnotations();
      this.buildKeyframes();
      this.t = this.lastT;
      this.seek(0);
    }

    // rows[y] strings (y = 0 bottom) → Int8Array by flat index y * W + x; '.' → -1.
    parseRows(rows, symbols) {
      const out = new Int8Array(this.W * this.H);
      for (let y = 0; y < this.H; ++y) {
        const row = rows[y];
        for (let x = 0; x < this.W; ++x) {
          const ch = row.charCodeAt(x);
          let v = -1;
          if (ch >= 48 && ch <= 57) v = ch - 48;
          else if (symbols && ch >= 65 && ch <= 90) v = ch - 55;
          out[y * this.W + x] = v;
        }
      }
      return out;
    }

    // All cell changes in two flat arrays; frame i's are [changeStart[i], changeStart[i + 1]).
    indexChanges() {
      const frames = this.trace.frames;
      let total = 0;
      for (const f of frames) total += f.c.length / 2;
      this.changeStart = new Int32Array(this.frameCount + 1);
      this.changeCell = new Int32Array(total);
      this.changeValue = new Int8Array(total);
      let j = 0;
      for (let i = 0; i < this.frameCount; ++i) {
        this.changeStart[i] = j;
        const c = frames[i].c;
        for (let k = 0; k < c.length; k += 2, ++j) {
          this.changeCell[j] = c[k];
          this.changeValue[j] = c[k + 1];
        }
      }
      this.changeStart[this.frameCount] = j;
    }

    // UAV states of every frame: [x, y, z, transit_left, active] per UAV.
    indexUavs() {
      const n5 = this.uavCount * 5;
      this.uav = new Int32Array(this.frameCount * n5);
      this.trace.frames.forEach((f, i) => this.uav.set(f.u, i * n5));
    }

    uavState(t, k) {
      const o = (t * this.uavCount + k) * 5;
      const u = this.uav;
      return {x: u[o], y: u[o + 1], z: u[o + 2], transit: u[o + 3], active: u[o + 4] === 1};
    }

    // Per UAV and per layer: the frames where the annotation changed, for binary search.
    indexAnnotations() {
      this.annotationTimes = Array.from({length: this.uavCount}, () => []);
      this.annotations = Array.from({length: this.uavCount}, () => []);
      this.layerNames = [];
      this.layerTimes = {};
      this.layerCells = {};
      this.trace.frames.forEach((f, t) => {
        if (f.p) {
          for (const key of Object.keys(f.p)) {
            const k = Number(key);
            if (!(k >= 0 && k < this.uavCount)) continue;
            this.annotationTimes[k].push(t);
            this.annotations[k].push(f.p[key]);
          }
        }
        if (f.l) {
          for (const name of Object.keys(f.l)) {
            if (!this.layerTimes[name]) {
              this.layerNames.push(name);
              this.layerTimes[name] = [];
              this.layerCells[name] = [];
            }
            this.layerTimes[name].push(t);
            this.layerCells[name].push(f.l[name]);
          }
        }
      });
      this.layerNames.sort((a, b) => (a === 'frontiers' ? -1 : b === 'frontiers' ? 1 : a < b ? -1 : 1));
    }

    annotation(k, t) {
      const i = lastAtOrBefore(this.annotationTimes[k], t);
      return i < 0 ? null : this.annotations[k][i];
    }

    layer(name, t) {
      const i = lastAtOrBefore(this.layerTimes[name], t);
      return i < 0 ? [] : this.layerCells[name][i];
    }

    applyFrame(i, map) {
      const end = this.changeStart[i + 1];
      for (let j = this.changeStart[i]; j < end; ++j) map[this.changeCell[j]] = this.changeValue[j];
    }

    buildKeyframes() {
      const map = this.parseRows(this.trace.initial_map);
      this.keyframes = [];
      for (let i = 0; i < this.frameCount; ++i) {
        this.applyFrame(i, map);
        if (i % KEYFRAME_INTERVAL === 0) this.keyframes.push(map.slice());
      }
      this.map = new Int8Array(map.length);
    }

    // Makes this.map the map M at time t.
    seek(t) {
      t = Math.max(0, Math.min(this.lastT, Math.round(t)));
      if (t === this.t) return t;
      let from;
      if (t > this.t && t - this.t < KEYFRAME_INTERVAL) {
        from = this.t + 1;
      } else {
        const k = Math.floor(t / KEYFRAME_INTERVAL);
        this.map.set(this.keyframes[k]);
        from = k * KEYFRAME_INTERVAL + 1;
      }
      for (let i = from; i <= t; ++i) this.applyFrame(i, this.map);
      this.t = t;
      return t;
    }

    coverage(t) {
      const r = this.trace.result;
      const s = this.trace.series;
      const c = r.corroded_cells > 0 ? (100 * s.inspected[t]) / r.corroded_cells : 100;
      const m = r.hull_cells > 0 ? (100 * s.known[t]) / r.hull_cells : 100;
      return {c, m};
    }
  }

  // ---------------------------------------------------------------------------------------------
  // The page: canvases, controls, chart, legend and tables.
  class Viewer {
    constructor(replay) {
      this.replay = replay;
      this.playing = false;
      this.speed = 10;
      this.cellPx = 5;
      this.dpr = window.devicePixelRatio || 1;
      this.hover = null;
      this.dirty = true;
      this.frameRequested = false;
      this.show = {};
      this.gridCanvas = $('grid-canvas');
      this.overlayCanvas = $('overlay-canvas');
      this.chartCanvas = $('chart-canvas');
      this.cellImage = new ImageData(replay.W, replay.H);
      this.cellCanvas = document.createElement('canvas');
      this.cellCanvas.width = replay.W;
      this.cellCanvas.height = replay.H;
      this.regionBoundary = replay.owner ? this.buildRegionBoundary() : null;
      this.fillTitle();
      this.fillStats();
      this.buildUavTable();
      this.bindControls();
      this.fillLegend();
      this.chooseDefaultSpeed();
      this.layout();
      this.seek(0);
    }

    // --- setup --------------------------------------------------------------------------------

    fillTitle() {
      const p = this.replay.trace.parameters || {};
      const parts = [];
      if (p.algorithm) parts.push(p.algorithm);
      parts.push(`${this.replay.uavCount} UAV${this.replay.uavCount === 1 ? '' : 's'}`);
      const fp = this.replay.trace.footprint;
      parts.push(`s1 = ${fp[0]}, s2 = ${fp[1]}`);
      if (p.seed !== undefined) parts.push(`seed ${p.seed}`);
      if (p.hull) parts.push(`hull ${p.hull}`);
      if (p.p_tp !== undefined) parts.push(`p_TP ${p.p_tp}, p_FP ${p.p_fp}`);
      parts.push(`${this.replay.W} × ${this.replay.H} cells`);
      $('mission-title').textContent = parts.join(' · ');
      document.title = `hullinspect replay: ${parts.slice(0, 2).join(', ')}`;
    }

    fillStats() {
      const r = this.replay.trace.result;
      const time = (t) => (t === null || t === undefined ? '— (not reached)' : `${t} s`);
      $('stat-tc').textContent = time(r.T_c);
      $('stat-tm').textContent = time(r.T_m);
      $('stat-mission').textContent =
          `${r.complete ? 'complete' : 'INCOMPLETE (time limit)'} after ${r.steps} steps · ` +
          `${r.hull_cells} hull cells, ${r.corroded_cells} corroded`;
      $('stat-counters').textContent =
          `moves ${r.moves} · plane changes ${r.plane_changes} · hovers ${r.hovers} · ` +
          `redundant observations ${r.redundant_observations}`;
      $('btn-tc').disabled = r.T_c === null || r.T_c === undefined;
      $('btn-tm').disabled = r.T_m === null || r.T_m === undefined;
    }

    fillLegend() {
      const items = [];
      const swatch = (style, cls = '') => `<span class="swatch ${cls}" style="${style}"></span>`;
      const cell = (c) => swatch(`background:${rgb(c)}`);
      items.push([cell(COLORS.nonHull), 'non-hull']);
      if (this.replay.owner && this.show.regions) {
        items.push([swatch(`background:linear-gradient(90deg,${rgb(regionColor(0))} 50%,` +
                           `${rgb(regionColor(1))} 50%)`), 'unknown (colour of its region)']);
        items.push([swatch(`background:linear-gradient(90deg,${rgb(regionTint(0))} 50%,` +
                           `${rgb(regionTint(1))} 50%)`), 'explored, clean (lighter tint)']);
      }
      if (!this.replay.owner || !this.show.regions) {
        items.push([cell(COLORS.unknown), 'unknown']);
        items.push([cell(COLORS.clean), 'explored, clean']);
      }
      items.push([cell(COLORS.corrosion), 'corrosion expected / detected (M = 2)']);
      items.push([cell(COLORS.inspected), 'corrosion inspected (M = 3)']);
      items.push([swatch(`background:${FOOTPRINT_FILL};border-color:#2878ff`), 'in sight (footprint)']);
      this.replay.layerNames.forEach((name, i) => {
        items.push([swatch(`background:${layerColor(name, i)}`), `${name} (planner layer)`]);
      });
      const c0 = uavColor(0);
      items.push([swatch('background:#fff;border:2px solid #333;outline:1px solid #fff'),
        'target of a UAV']);
      items.push([swatch(`background:#fff;border-color:${c0}`, 'marker'), 'UAV at z = 2 (detection)']);
      items.push([swatch(`background:${c0};border-color:#fff;outline:1px solid ${c0}`, 'marker'),
        'UAV at z = 1 (close-up)']);
      items.push([swatch(`background:linear-gradient(90deg,${c0} 50%,#fff 50%);border-color:${c0}`,
                         'marker'), 'UAV changing plane']);
      items.push([swatch(`border-color:${c0}`, 'line'), 'recent path at z = 1']);
      items.push([swatch(`border-color:${c0}`, 'line dashed'), 'recent path at z = 2']);
      items.push([swatch(`border-color:${c0};border-top-width:1px;opacity:0.6`, 'line'),
        'plan: waypoints ahead (x first, then y)']);
      if (this.replay.owner && this.show.regions) {
        items.push([swatch('border-color:#111', 'line'), 'region boundary']);
      }
      $('legend').innerHTML = items.map(([s, text]) => `<li>${s}<span>${text}</span></li>`).join('');
    }

    buildUavTable() {
      const body = $('uav-table').querySelector('tbody');
      body.innerHTML = '';
      this.uavRows = [];
      for (let k = 0; k < this.replay.uavCount; ++k) {
        const tr = document.createElement('tr');
        tr.innerHTML = `<td><span class="swatch marker" style="background:${uavColor(k)};` +
            `border-color:${uavColor(k)}"></span> ${k}</td><td class="num"></td><td></td><td></td>` +
            '<td class="num"></td>';
        body.appendChild(tr);
        this.uavRows.push(Array.from(tr.children).slice(1));
      }
    }

    chooseDefaultSpeed() {
      // About 30 s for the whole mission.
      const options = Array.from($('speed').options).map((o) => Number(o.value));
      const wanted = this.replay.lastT / 30;
      this.speed = options.reduce((best, v) => (Math.abs(v - wanted) < Math.abs(best - wanted) ? v : best),
                                  options[0]);
      $('speed').value = String(this.speed);
    }

    bindControls() {
      const r = this.replay;
      const slider = $('slider');
      slider.max = String(r.lastT);
      const button = (id, fn) => {
        const b = $(id);
        b.addEventListener('mousedown', (e) => e.preventDefault()); // keep the keyboard focus
        b.addEventListener('click', fn);
      };
      button('btn-start', () => this.seek(0));
      button('btn-back', () => this.seek(r.t - 1));
      button('btn-play', () => this.togglePlay());
      button('btn-forward', () => this.seek(r.t + 1));
      button('btn-end', () => this.seek(r.lastT));
      button('btn-tc', () => this.seek(r.trace.result.T_c));
      button('btn-tm', () => this.seek(r.trace.result.T_m));
      slider.addEventListener('input', () => { this.pause(); this.seek(Number(slider.value)); });
      $('speed').addEventListener('change', (e) => { this.speed = Number(e.target.value); e.target.blur(); });
      $('zoom').addEventListener('change', (e) => { this.layout(); e.target.blur(); });
      for (const name of ['footprints', 'paths', 'plans', 'targets', 'layers', 'labels', 'regions']) {
        const box = $(`show-${name}`);
        this.show[name] = box.checked;
        box.addEventListener('change', () => {
          this.show[name] = box.checked;
          box.blur();
          if (name === 'regions') this.fillLegend();
          this.requestDraw();
        });
      }
      if (!r.owner) $('show-regions').parentElement.hidden = true;
      if (r.layerNames.length === 0) $('show-layers').parentElement.hidden = true;
      document.addEventListener('keydown', (e) => this.onKey(e));
      window.addEventListener('resize', () => this.layout());
      this.overlayCanvas.addEventListener('mousemove', (e) => this.onHover(e));
      this.overlayCanvas.addEventListener('mouseleave', () => { this.hover = null; this.requestDraw(); });
      const chartSeek = (e) => {
        if (!(e.buttons & 1) && e.type !== 'mousedown') return;
        const rect = this.chartCanvas.getBoundingClientRect();
        this.pause();
        this.seek(this.chartTimeAt(e.clientX - rect.left));
      };
      this.chartCanvas.addEventListener('mousedown', chartSeek);
      this.chartCanvas.addEventListener('mousemove', chartSeek);
    }

    onKey(e) {
      if (e.altKey || e.ctrlKey || e.metaKey) return;
      const tag = e.target && e.target.tagName;
      if (tag === 'SELECT' || (tag === 'INPUT' && e.target.type !== 'range' && e.target.type !== 'checkbox')) return;
      const r = this.replay;
      const step = e.shiftKey ? 10 : 1;
      const speeds = Array.from($('speed').options).map((o) => Number(o.value));
      const speedIndex = speeds.indexOf(this.speed);
      let handled = true;
      switch (e.key) {
        case ' ': this.togglePlay(); break;
        case 'ArrowRight': this.pause(); this.seek(r.t + step); break;
        case 'ArrowLeft': this.pause(); this.seek(r.t - step); break;
        case 'PageDown': this.pause(); this.seek(r.t + 100); break;
        case 'PageUp': this.pause(); this.seek(r.t - 100); break;
        case 'Home': this.pause(); this.seek(0); break;
        case 'End': this.pause(); this.seek(r.lastT); break;
        case 'c': case 'C': if (r.trace.result.T_c !== null) { this.pause(); this.seek(r.trace.result.T_c); } break;
        case 'm': case 'M': if (r.trace.result.T_m !== null) { this.pause(); this.seek(r.trace.result.T_m); } break;
        case '+': case '=': this.setSpeed(speeds[Math.min(speeds.length - 1, speedIndex + 1)]); break;
        case '-': case '_': this.setSpeed(speeds[Math.max(0, speedIndex - 1)]); break;
        default: handled = false;
      }
      if (handled) e.preventDefault();
    }

    setSpeed(v) {
      if (v === undefined) return;
      this.speed = v;
      $('speed').value = String(v);
    }

    // --- layout ---------------------------------------------------------------------------------

    layout() {
      const r = this.replay;
      const zoom = Number($('zoom').value);
      const avail = Math.max(100, $('map-scroll').clientWidth);
      // Fit: the whole width, cells may be a fraction of a pixel wider than others on screen.
      this.cellPx = zoom > 0 ? zoom : Math.max(2, avail / r.W);
      this.dpr = window.devicePixelRatio || 1;
      const w = Math.floor(r.W * this.cellPx);
      this.cellPx = w / r.W;
      const h = Math.round(r.H * this.cellPx);
      for (const c of [this.gridCanvas, this.overlayCanvas]) {
        c.style.width = `${w}px`;
        c.style.height = `${h}px`;
        c.width = Math.round(w * this.dpr);
        c.height = Math.round(h * this.dpr);
      }
      $('map-stack').style.width = `${w}px`;
      const cw = this.chartCanvas.clientWidth || 600;
      const ch = this.chartCanvas.clientHeight || 220;
      this.chartCanvas.width = Math.round(cw * this.dpr);
      this.chartCanvas.height = Math.round(ch * this.dpr);
      this.chartSize = {w: cw, h: ch, left: 44, right: 12, top: 12, bottom: 26};
      this.chartBackground = this.drawChartBackground();
      this.requestDraw();
    }

    // Region boundaries as one path in cell units (y down), built once.
    buildRegionBoundary() {
      const {W, H, owner} = this.replay;
      const segments = [];
      const at = (x, y) => owner[y * W + x];
      for (let y = 0; y < H; ++y) {
        for (let x = 0; x < W; ++x) {
          const o = at(x, y);
          if (o < 0) continue;
          const row = H - 1 - y; // canvas row of this cell
          // Edges towards a different, assigned region (each shared edge once: right and up).
          if (x + 1 < W && at(x + 1, y) >= 0 && at(x + 1, y) !== o) segments.push([x + 1, row, x + 1, row + 1]);
          if (y + 1 < H && at(x, y + 1) >= 0 && at(x, y + 1) !== o) segments.push([x, row, x + 1, row]);
        }
      }
      return segments;
    }

    // --- time -----------------------------------------------------------------------------------

    seek(t) {
      if (t === null || t === undefined || Number.isNaN(t)) return;
      this.replay.seek(t);
      this.requestDraw();
    }

    togglePlay() { if (this.playing) this.pause(); else this.play(); }

    play() {
      if (this.replay.t >= this.replay.lastT) this.replay.seek(0);
      this.playing = true;
      this.playClock = performance.now();
      this.playCarry = 0;
      $('btn-play').classList.add('active');
      this.requestDraw();
    }

    pause() {
      if (!this.playing) return;
      this.playing = false;
      $('btn-play').classList.remove('active');
    }

    requestDraw() {
      this.dirty = true;
      if (this.frameRequested) return;
      this.frameRequested = true;
      requestAnimationFrame((now) => this.onFrame(now));
    }

    onFrame(now) {
      this.frameRequested = false;
      if (this.playing) {
        const elapsed = Math.min(0.25, (now - this.playClock) / 1000); // a hidden tab does not jump
        this.playClock = now;
        this.playCarry += elapsed * this.speed;
        const steps = Math.floor(this.playCarry);
        if (steps > 0) {
          this.playCarry -= steps;
          this.replay.seek(Math.min(this.replay.lastT, this.replay.t + steps));
          this.dirty = true;
        }
        if (this.replay.t >= this.replay.lastT) this.pause();
      }
      if (this.dirty) {
        this.dirty = false;
        const start = performance.now();
        this.draw();
        this.lastDrawMs = performance.now() - start;
      }
      if (this.playing) {
        this.frameRequested = true;
        requestAnimationFrame((n) => this.onFrame(n));
      }
    }

    // --- drawing --------------------------------------------------------------------------------

    draw() {
      this.drawCells();
      this.drawOverlay();
      this.drawChart();
      this.updateText();
    }

    cellColor(i) {
      const v = this.replay.map[i];
      if (v < 0) return COLORS.nonHull;
      if (v === 2) return COLORS.corrosion;
      if (v === 3) return COLORS.inspected;
      const o = this.replay.owner && this.show.regions ? this.replay.owner[i] : -1;
      if (o >= 0) return v === 0 ? regionColor(o) : regionTint(o);
      return v === 0 ? COLORS.unknown : COLORS.clean;
    }

    drawCells() {
      const {W, H} = this.replay;
      const data = this.cellImage.data;
      for (let y = 0; y < H; ++y) {
        let p = (H - 1 - y) * W * 4;
        for (let x = 0; x < W; ++x, p += 4) {
          const c = this.cellColor(y * W + x);
          data[p] = c[0];
          data[p + 1] = c[1];
          data[p + 2] = c[2];
          data[p + 3] = 255;
        }
      }
      this.cellCanvas.getContext('2d').putImageData(this.cellImage, 0, 0);
      const ctx = this.gridCanvas.getContext('2d');
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(this.cellCanvas, 0, 0, this.gridCanvas.width, this.gridCanvas.height);
      if (this.regionBoundary && this.show.regions) {
        const s = this.cellPx * this.dpr;
        ctx.strokeStyle = 'rgba(17, 17, 17, 0.8)';
        ctx.lineWidth = Math.max(1, Math.round(this.dpr));
        ctx.beginPath();
        for (const [x0, y0, x1, y1] of this.regionBoundary) {
          ctx.moveTo(x0 * s, y0 * s);
          ctx.lineTo(x1 * s, y1 * s);
        }
        ctx.stroke();
      }
    }

    // Canvas coordinates (CSS px) of a cell's centre; y = 0 is the bottom row.
    cx(x) { return (x + 0.5) * this.cellPx; }
    cy(y) { return (this.replay.H - 1 - y + 0.5) * this.cellPx; }

    drawOverlay() {
      const r = this.replay;
      const ctx = this.overlayCanvas.getContext('2d');
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
      ctx.clearRect(0, 0, r.W * this.cellPx, r.H * this.cellPx);
      const cp = this.cellPx;
      const t = r.t;
      if (this.show.layers) {
        r.layerNames.forEach((name, i) => {
          ctx.fillStyle = layerColor(name, i);
          for (const c of r.layer(name, t)) {
            const x = c % r.W;
            const y = (c - x) / r.W;
            ctx.fillRect(x * cp, (r.H - 1 - y) * cp, cp, cp);
          }
        });
      }
      const states = [];
      for (let k = 0; k < r.uavCount; ++k) states.push(r.uavState(t, k));
      if (this.show.footprints) {
        const fp = r.trace.footprint;
        states.forEach((s, k) => {
          if (!s.active) return;
          const half = ((s.z === 1 ? fp[0] : fp[1]) - 1) / 2;
          const x0 = Math.max(0, s.x - half) * cp;
          const x1 = Math.min(r.W, s.x + half + 1) * cp;
          const yTop = (r.H - 1 - Math.min(r.H - 1, s.y + half)) * cp;
          const yBottom = (r.H - Math.max(0, s.y - half)) * cp;
          ctx.setLineDash(s.transit > 0 ? [3, 3] : []);
          if (s.transit === 0) { // a UAV changing plane does not sense
            ctx.fillStyle = FOOTPRINT_FILL;
            ctx.fillRect(x0, yTop, x1 - x0, yBottom - yTop);
          }
          ctx.strokeStyle = uavColor(k);
          ctx.lineWidth = 1.5;
          ctx.strokeRect(x0 + 0.75, yTop + 0.75, x1 - x0 - 1.5, yBottom - yTop - 1.5);
        });
        ctx.setLineDash([]);
      }
      if (this.show.paths) this.drawPaths(ctx, t);
      const notes = [];
      for (let k = 0; k < r.uavCount; ++k) notes.push(r.annotation(k, t));
      if (this.show.plans) {
        notes.forEach((a, k) => { if (a && a.plan && a.plan.length) this.drawPlan(ctx, states[k], a.plan, k); });
      }
      if (this.show.targets) {
        notes.forEach((a, k) => {
          if (!a || !a.target) return;
          const [x, y] = a.target;
          const px = x * cp;
          const py = (r.H - 1 - y) * cp;
          const pad = Math.max(1, cp * 0.15);
          ctx.fillStyle = '#ffffff';
          ctx.fillRect(px - pad, py - pad, cp + 2 * pad, cp + 2 * pad);
          ctx.strokeStyle = uavColor(k);
          ctx.lineWidth = 2;
          ctx.strokeRect(px - pad, py - pad, cp + 2 * pad, cp + 2 * pad);
        });
      }
      states.forEach((s, k) => this.drawUav(ctx, s, k));
      if (this.show.labels) this.drawLabels(ctx, states, notes);
      if (this.hover) {
        const {x, y} = this.hover;
        ctx.lineWidth = 1.5;
        ctx.strokeStyle = '#000';
        ctx.strokeRect(x * cp - 1, (r.H - 1 - y) * cp - 1, cp + 2, cp + 2);
        ctx.strokeStyle = '#fff';
        ctx.strokeRect(x * cp - 2.5, (r.H - 1 - y) * cp - 2.5, cp + 5, cp + 5);
      }
    }

    // "k mode" beside each UAV, moved to another corner of the marker when it would cover a label
    // already placed.
    drawLabels(ctx, states, notes) {
      ctx.font = '600 11px system-ui, sans-serif';
      ctx.textBaseline = 'middle';
      ctx.lineJoin = 'round';
      const rad = this.markerRadius();
      const width = this.replay.W * this.cellPx;
      const height = this.replay.H * this.cellPx;
      const placed = [];
      const overlaps = (b) => placed.some((p) => b.x < p.x + p.w && p.x < b.x + b.w && b.y < p.y + p.h && p.y < b.y + b.h);
      states.forEach((s, k) => {
        const a = notes[k];
        const text = a && a.mode ? `${k} ${a.mode}` : `${k}`;
        const w = ctx.measureText(text).width + 2;
        const h = 12;
        const x = this.cx(s.x);
        const y = this.cy(s.y);
        const candidates = [
          [x + rad, y - rad - h], [x + rad, y + rad], [x - rad - w, y - rad - h], [x - rad - w, y + rad],
          [x + rad + 1, y - h / 2], [x - rad - w - 1, y - h / 2],
        ].map(([bx, by]) => ({x: Math.max(0, Math.min(width - w, bx)), y: Math.max(0, Math.min(height - h, by)), w, h}));
        const box = candidates.find((b) => !overlaps(b)) || candidates[0];
        placed.push(box);
        ctx.strokeStyle = 'rgba(255, 255, 255, 0.9)';
        ctx.lineWidth = 3;
        ctx.strokeText(text, box.x + 1, box.y + h / 2);
        ctx.fillStyle = uavColor(k);
        ctx.fillText(text, box.x + 1, box.y + h / 2);
      });
    }

    markerRadius() { return Math.max(4.5, Math.min(10, this.cellPx * 0.9)); }

    // The last PATH_LENGTH steps: solid where the UAV was at z = 1, dashed at z = 2, older steps
    // fainter. Segments are batched into one path per (age bucket, plane) to keep strokes few.
    drawPaths(ctx, t) {
      const r = this.replay;
      const from = Math.max(0, t - PATH_LENGTH);
      const buckets = 4;
      ctx.lineCap = 'round';
      for (let k = 0; k < r.uavCount; ++k) {
        ctx.strokeStyle = uavColor(k);
        for (let b = 0; b < buckets; ++b) {
          for (const closeUp of [false, true]) {
            ctx.beginPath();
            let any = false;
            for (let i = from; i < t; ++i) {
              if (Math.min(buckets - 1, Math.floor(((i - from) * buckets) / (t - from))) !== b) continue;
              const a = r.uavState(i, k);
              const c = r.uavState(i + 1, k);
              if (a.x === c.x && a.y === c.y) continue;
              if ((a.z === 1 && a.transit === 0 && c.z === 1) !== closeUp) continue;
              ctx.moveTo(this.cx(a.x), this.cy(a.y));
              ctx.lineTo(this.cx(c.x), this.cy(c.y));
              any = true;
            }
            if (!any) continue;
            ctx.globalAlpha = 0.3 + (0.7 * (b + 1)) / buckets;
            ctx.lineWidth = closeUp ? 2.5 : 1.5;
            ctx.setLineDash(closeUp ? [] : [3, 2]);
            ctx.stroke();
          }
        }
      }
      ctx.globalAlpha = 1;
      ctx.setLineDash([]);
    }

    // Waypoints joined the way UAVs fly between them (along x first, then along y).
    drawPlan(ctx, s, plan, k) {
      // Solid and thin: a dashed pattern over long plans costs more than the rest of the frame.
      ctx.strokeStyle = uavColor(k);
      ctx.globalAlpha = 0.6;
      ctx.lineWidth = 1;
      ctx.beginPath();
      let x = s.x;
      let y = s.y;
      ctx.moveTo(this.cx(x), this.cy(y));
      for (const [wx, wy] of plan) {
        ctx.lineTo(this.cx(wx), this.cy(y));
        ctx.lineTo(this.cx(wx), this.cy(wy));
        x = wx;
        y = wy;
      }
      ctx.stroke();
      ctx.fillStyle = uavColor(k);
      const d = Math.max(2, this.cellPx * 0.4);
      for (const [wx, wy] of plan) ctx.fillRect(this.cx(wx) - d / 2, this.cy(wy) - d / 2, d, d);
      ctx.globalAlpha = 1;
    }

    drawUav(ctx, s, k) {
      const x = this.cx(s.x);
      const y = this.cy(s.y);
      const rad = this.markerRadius();
      const color = s.active ? uavColor(k) : '#777';
      ctx.beginPath();
      ctx.arc(x, y, rad, 0, 2 * Math.PI);
      if (!s.active) {
        ctx.fillStyle = '#bbb';
      } else if (s.transit > 0) {
        const g = ctx.createLinearGradient(x - rad, 0, x + rad, 0);
        g.addColorStop(0.5, color);
        g.addColorStop(0.5, '#fff');
        ctx.fillStyle = g;
      } else {
        ctx.fillStyle = s.z === 1 ? color : '#fff';
      }
      ctx.fill();
      ctx.lineWidth = s.z === 1 && s.transit === 0 ? 1.5 : 2.5;
      ctx.strokeStyle = s.z === 1 && s.transit === 0 && s.active ? '#fff' : color;
      ctx.stroke();
      if (s.z === 1 && s.transit === 0 && s.active) {
        ctx.beginPath();
        ctx.arc(x, y, rad + 1.25, 0, 2 * Math.PI);
        ctx.lineWidth = 1;
        ctx.strokeStyle = color;
        ctx.stroke();
      }
      if (!s.active) {
        ctx.strokeStyle = '#333';
        ctx.lineWidth = 1.5;
        ctx.beginPath();
        ctx.moveTo(x - rad * 0.6, y - rad * 0.6);
        ctx.lineTo(x + rad * 0.6, y + rad * 0.6);
        ctx.moveTo(x + rad * 0.6, y - rad * 0.6);
        ctx.lineTo(x - rad * 0.6, y + rad * 0.6);
        ctx.stroke();
      }
    }

    // --- chart ----------------------------------------------------------------------------------

    chartX(t) {
      const s = this.chartSize;
      return s.left + ((s.w - s.left - s.right) * t) / Math.max(1, this.replay.lastT);
    }

    chartY(percent) {
      const s = this.chartSize;
      return s.top + ((s.h - s.top - s.bottom) * (100 - percent)) / 100;
    }

    chartTimeAt(px) {
      const s = this.chartSize;
      return Math.round(((px - s.left) / (s.w - s.left - s.right)) * this.replay.lastT);
    }

    // Axes, both series and the T_c / T_m markers, drawn once per layout.
    drawChartBackground() {
      const r = this.replay;
      const s = this.chartSize;
      const canvas = document.createElement('canvas');
      canvas.width = this.chartCanvas.width;
      canvas.height = this.chartCanvas.height;
      const ctx = canvas.getContext('2d');
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
      ctx.font = '11px system-ui, sans-serif';
      ctx.fillStyle = '#5c6570';
      ctx.strokeStyle = '#e3e6ea';
      ctx.lineWidth = 1;
      ctx.textAlign = 'right';
      ctx.textBaseline = 'middle';
      for (let p = 0; p <= 100; p += 25) {
        const y = Math.round(this.chartY(p)) + 0.5;
        ctx.beginPath();
        ctx.moveTo(s.left, y);
        ctx.lineTo(s.w - s.right, y);
        ctx.stroke();
        ctx.fillText(`${p} %`, s.left - 4, y);
      }
      const tick = niceStep(r.lastT / 8);
      ctx.textAlign = 'center';
      ctx.textBaseline = 'top';
      for (let t = 0; t <= r.lastT; t += tick) {
        const x = Math.round(this.chartX(t)) + 0.5;
        ctx.beginPath();
        ctx.moveTo(x, s.top);
        ctx.lineTo(x, s.h - s.bottom);
        ctx.stroke();
        const label = `${t}`;
        const half = ctx.measureText(label).width / 2;
        ctx.fillText(label, Math.min(x, s.w - half - 1), s.h - s.bottom + 4);
      }
      ctx.textAlign = 'right';
      ctx.fillText('t (s)', s.left - 8, s.h - s.bottom + 4);
      const series = [['m', 'rgb(31, 111, 235)'], ['c', rgb(COLORS.inspected)]];
      for (const [key, color] of series) {
        ctx.strokeStyle = color;
        ctx.lineWidth = 2;
        ctx.beginPath();
        for (let t = 0; t <= r.lastT; ++t) {
          const v = r.coverage(t)[key];
          if (t === 0) ctx.moveTo(this.chartX(t), this.chartY(v)); else ctx.lineTo(this.chartX(t), this.chartY(v));
        }
        ctx.stroke();
      }
      const marks = [['T_c', r.trace.result.T_c, rgb(COLORS.inspected)], ['T_m', r.trace.result.T_m, 'rgb(31, 111, 235)']];
      ctx.setLineDash([4, 3]);
      ctx.textAlign = 'left';
      ctx.textBaseline = 'top';
      ctx.font = '600 11px system-ui, sans-serif';
      marks.forEach(([name, t, color], i) => {
        if (t === null || t === undefined) return;
        const x = this.chartX(t);
        ctx.strokeStyle = color;
        ctx.lineWidth = 1.25;
        ctx.beginPath();
        ctx.moveTo(x, s.top);
        ctx.lineTo(x, s.h - s.bottom);
        ctx.stroke();
        ctx.fillStyle = color;
        const label = `${name} = ${t}`;
        const w = ctx.measureText(label).width;
        const lx = x + 3 + w > s.w - s.right ? x - 3 - w : x + 3;
        ctx.fillText(label, lx, s.h - s.bottom - 28 + i * 13);
      });
      ctx.setLineDash([]);
      ctx.font = '11px system-ui, sans-serif';
      ctx.textAlign = 'left';
      ctx.fillStyle = rgb(COLORS.inspected);
      ctx.textBaseline = 'top';
      ctx.fillText('c(t): corroded cells inspected', s.left + 6, s.top + 4);
      ctx.fillStyle = 'rgb(31, 111, 235)';
      ctx.fillText('m(t): hull cells known', s.left + 6, s.top + 18);
      return canvas;
    }

    drawChart() {
      const r = this.replay;
      const s = this.chartSize;
      const ctx = this.chartCanvas.getContext('2d');
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.clearRect(0, 0, this.chartCanvas.width, this.chartCanvas.height);
      ctx.drawImage(this.chartBackground, 0, 0);
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
      const x = this.chartX(r.t);
      ctx.strokeStyle = '#1d2228';
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(x, s.top);
      ctx.lineTo(x, s.h - s.bottom);
      ctx.stroke();
      const v = r.coverage(r.t);
      for (const [value, color] of [[v.m, 'rgb(31, 111, 235)'], [v.c, rgb(COLORS.inspected)]]) {
        ctx.beginPath();
        ctx.arc(x, this.chartY(value), 4, 0, 2 * Math.PI);
        ctx.fillStyle = color;
        ctx.fill();
        ctx.strokeStyle = '#fff';
        ctx.lineWidth = 1.5;
        ctx.stroke();
      }
    }

    // --- text -----------------------------------------------------------------------------------

    updateText() {
      const r = this.replay;
      const t = r.t;
      $('slider').value = String(t);
      $('time-display').textContent = `t = ${t} s / ${r.lastT}`;
      $('uav-time').textContent = String(t);
      const v = r.coverage(t);
      $('now-c').textContent = v.c.toFixed(1);
      $('now-m').textContent = v.m.toFixed(1);
      for (let k = 0; k < r.uavCount; ++k) {
        const s = r.uavState(t, k);
        const a = r.annotation(k, t);
        const cells = this.uavRows[k];
        cells[0].textContent = `(${s.x}, ${s.y})`;
        cells[1].textContent = !s.active ? 'failed'
            : s.transit > 0 ? `z ${s.z}→${3 - s.z} (${s.transit} left)` : `z = ${s.z}`;
        cells[2].textContent = a && a.mode ? a.mode : '—';
        cells[3].textContent = a && a.target ? `(${a.target[0]}, ${a.target[1]})` : '—';
      }
      this.updateHoverInfo();
    }

    onHover(e) {
      const rect = this.overlayCanvas.getBoundingClientRect();
      const x = Math.floor((e.clientX - rect.left) / this.cellPx);
      const row = Math.floor((e.clientY - rect.top) / this.cellPx);
      const y = this.replay.H - 1 - row;
      if (x < 0 || x >= this.replay.W || y < 0 || y >= this.replay.H) {
        this.hover = null;
      } else if (!this.hover || this.hover.x !== x || this.hover.y !== y) {
        this.hover = {x, y};
      } else {
        return;
      }
      this.requestDraw();
    }

    updateHoverInfo() {
      const info = $('hover-info');
      if (!this.hover) {
        info.textContent = 'Hover over a cell to see its state.';
        return;
      }
      const r = this.replay;
      const {x, y} = this.hover;
      const i = y * r.W + x;
      const size = r.trace.grid.cell_size_m;
      const parts = [`cell (${x}, ${y})`];
      if (size) parts.push(`${(x * size).toFixed(1)} m × ${(y * size).toFixed(1)} m`);
      const m = r.map[i];
      if (m < 0) {
        parts.push('non-hull');
      } else {
        parts.push(`M = ${m} ${M_NAMES[m]}`);
        parts.push(`truth C = ${r.truth[i]}`);
        parts.push(`prior C' = ${r.prior[i]}`);
        if (r.owner && r.owner[i] >= 0) parts.push(`region of UAV ${r.owner[i]}`);
      }
      const inLayers = r.layerNames.filter((name) => r.layer(name, r.t).includes(i));
      if (inLayers.length) parts.push(`layer ${inLayers.join(', ')}`);
      const fp = r.trace.footprint;
      const sight = [];
      const here = [];
      const targets = [];
      for (let k = 0; k < r.uavCount; ++k) {
        const s = r.uavState(r.t, k);
        const half = ((s.z === 1 ? fp[0] : fp[1]) - 1) / 2;
        if (s.active && s.transit === 0 && Math.abs(s.x - x) <= half && Math.abs(s.y - y) <= half) sight.push(k);
        if (s.x === x && s.y === y) here.push(k);
        const a = r.annotation(k, r.t);
        if (a && a.target && a.target[0] === x && a.target[1] === y) targets.push(k);
      }
      if (here.length) parts.push(`UAV ${here.join(', ')} here`);
      if (sight.length) parts.push(`in sight of UAV ${sight.join(', ')}`);
      if (targets.length) parts.push(`target of UAV ${targets.join(', ')}`);
      info.textContent = parts.join(' · ');
    }
  }

  // 1, 2, 5 × 10^k at least `raw`.
  function niceStep(raw) {
    if (!(raw > 0)) return 1;
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    for (const m of [1, 2, 5, 10]) if (m * p >= raw) return Math.max(1, m * p);
    return 10 * p;
  }

  // ---------------------------------------------------------------------------------------------
  // Start-up: the embedded trace, or a trace file chosen or dropped by the user.

  // Timings (ms since navigation) are kept for the browser test's measurements.
  const api = {ready: false, error: null, scriptAt: performance.now()};
  window.hullViewer = api;

  function start(trace) {
    const t0 = performance.now();
    try {
      const replay = new Replay(trace);
      $('viewer').hidden = false;
      $('file-picker').hidden = true;
      $('load-error').hidden = true;
      const viewer = new Viewer(replay);
      Object.assign(api, {
        replay,
        viewer,
        seek: (t) => viewer.seek(t),
        time: () => replay.t,
        play: () => viewer.play(),
        pause: () => viewer.pause(),
        mapAt: (t) => { viewer.seek(t); return Array.from(replay.map); },
        setupMs: performance.now() - t0,
        readyAt: performance.now(),
        ready: true,
      });
    } catch (e) {
      showError(`Cannot show this trace: ${e.message}`);
    }
  }

  function showError(message) {
    api.error = message;
    const el = $('load-error');
    el.textContent = message;
    el.hidden = false;
  }

  function readFile(file) {
    const reader = new FileReader();
    reader.onload = () => {
      let trace;
      try {
        trace = JSON.parse(reader.result);
      } catch (e) {
        showError(`${file.name} is not JSON: ${e.message}`);
        return;
      }
      start(trace);
    };
    reader.readAsText(file);
  }

  const embedded = $('trace-data').textContent.trim();
  if (embedded) {
    let trace = null;
    try {
      const parseStart = performance.now();
      trace = JSON.parse(embedded);
      api.parseMs = performance.now() - parseStart;
    } catch (e) {
      showError(`The embedded trace is not JSON: ${e.message}`);
    }
    if (trace) start(trace);
  } else {
    $('file-picker').hidden = false;
    $('trace-file').addEventListener('change', (e) => { if (e.target.files[0]) readFile(e.target.files[0]); });
    document.addEventListener('dragover', (e) => e.preventDefault());
    document.addEventListener('drop', (e) => {
      e.preventDefault();
      if (e.dataTransfer.files[0]) readFile(e.dataTransfer.files[0]);
    });
  }
})();
