// The replay viewer's page (docs/viewer.md): controls, legend, tables, the hover line and playback,
// around the map (map_view.js) and the progress chart (chart.js) of a replay (replay.js).
// Plain browser JavaScript, no dependencies, nothing fetched.
'use strict';

(function (hv) {
  const {COLORS, FOOTPRINT_FILL, TRUTH_MARK, HOVER_MARK, NO_FLY_MARK, UNREACHABLE_MARK, M_NAMES, rgb,
    regionColor, regionTint, uavColor, layerColor, LAUNCH_SITE_FILL, GROUND_FILL, AWAY_FILL, BATTERY_OK,
    BATTERY_LOW} = hv.palette;
  const $ = (id) => document.getElementById(id);

  class Viewer {
    constructor(replay, options = {}) {
      this.replay = replay;
      this.playing = false;
      this.speed = 10;
      this.dirty = true;
      this.frameRequested = false;
      this.show = {};
      this.map = new hv.MapView(replay, $('grid-canvas'), $('overlay-canvas'), this.show);
      this.chart = new hv.ProgressChart(replay, $('chart-canvas'));
      this.view3d = null; // built on the first switch to 3D
      this.mode3d = false;
      this.fillTitle();
      this.fillStats();
      this.buildUavTable();
      this.bindControls();
      this.fillLegend();
      this.chooseDefaultSpeed();
      this.layout();
      this.seek(0);
      if (options.start_3d) this.toggle3d();
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
      if (p.prior_file) parts.push(`prior ${p.prior_file}`);
      if (p.truth_file) parts.push(`truth ${p.truth_file}`);
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
          `${r.hull_cells} hull cells, ${r.corroded_cells} corroded` +
          (r.unreachable_cells ? `, ${r.unreachable_cells} unreachable for close-up (not counted in c(t), m(t))` : '');
      $('stat-counters').textContent =
          `moves ${r.moves} · plane changes ${r.plane_changes} · hovers ${r.hovers} · ` +
          `redundant observations ${r.redundant_observations}` +
          (r.sorties !== undefined ? ` · sorties ${r.sorties}` : '') +
          (r.battery_crashes !== undefined ? ` · battery crashes ${r.battery_crashes}` : '');
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
      items.push([cell(COLORS.priorOnly), 'corrosion expected from the prior, not seen yet (M = 2)']);
      items.push([cell(COLORS.corrosion), 'corrosion detected (M = 2)']);
      items.push([cell(COLORS.inspected), 'corrosion inspected (M = 3)']);
      items.push([swatch(`background:${FOOTPRINT_FILL};border-color:#2878ff`), 'in sight (footprint)']);
      // Hatching as map_view.js draws it (drawNoFly): no-fly '/', unreachable '\\'.
      const hatch = (angle, color) => swatch(`background:repeating-linear-gradient(${angle}deg,` +
                                             `${color} 0 1.5px,transparent 1.5px 5px),${rgb(COLORS.clean)}`, 'hatch');
      if (this.replay.noFly) items.push([hatch(-45, NO_FLY_MARK), 'no-fly position (no UAV may be there)']);
      if (this.replay.unreachable) {
        items.push([hatch(45, UNREACHABLE_MARK[1]), 'unreachable for close-up: only z = 2 sees it']);
        items.push([hatch(45, UNREACHABLE_MARK[2]), 'unreachable: no footprint sees it']);
      }
      this.replay.layerNames.forEach((name, i) => {
        items.push([swatch(`background:${layerColor(name, i)}`), `${name} (planner layer)`]);
      });
      const c0 = uavColor(0);
      items.push([swatch('background:#fff;border:2px solid #333;outline:1px solid #fff'),
        'target of a UAV']);
      items.push([swatch(`border:2px solid ${HOVER_MARK};outline:1px solid #000`), 'cell under the mouse']);
      if (this.show.truth) {
        items.push([swatch(`background:radial-gradient(${TRUTH_MARK} 45%, transparent 50%)`),
          'corrosion not detected yet (truth; planners do not see it)']);
      }
      items.push([swatch(`background:#fff;border-color:${c0}`, 'marker'), 'UAV at z = 2 (detection)']);
      items.push([swatch(`background:${c0};border-color:#fff;outline:1px solid ${c0}`, 'marker'),
        'UAV at z = 1 (close-up)']);
      items.push([swatch(`background:linear-gradient(90deg,${c0} 50%,#fff 50%);border-color:${c0}`,
                         'marker'), 'UAV changing plane']);
      if (this.replay.physical) {
        items.push([swatch(`background:${LAUNCH_SITE_FILL};border:1.5px solid #111`), 'launch site']);
        items.push([swatch(`background:${GROUND_FILL};border-color:${c0};clip-path:polygon(50% 0,100% 100%,0 100%)`,
                           'marker'), 'UAV on the ground at its launch site']);
        items.push([swatch(`background:${AWAY_FILL};border-color:${c0};transform:rotate(45deg);border-radius:0`,
                           'marker'), 'UAV away: flying between its launch site and the hull']);
      }
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
      // With launch sites: whether each UAV is airborne, on the ground or away; with a battery, its
      // gauge.
      const head = $('uav-table').querySelector('thead tr');
      if (this.replay.physical) head.insertAdjacentHTML('beforeend', '<th>flight</th>');
      if (this.replay.battery) head.insertAdjacentHTML('beforeend', '<th>battery</th>');
      const body = $('uav-table').querySelector('tbody');
      body.innerHTML = '';
      this.uavRows = [];
      for (let k = 0; k < this.replay.uavCount; ++k) {
        const tr = document.createElement('tr');
        tr.innerHTML = `<td><span class="swatch marker" style="background:${uavColor(k)};` +
            `border-color:${uavColor(k)}"></span> ${k}</td><td class="num"></td><td></td><td></td>` +
            '<td class="num"></td>' +
            (this.replay.physical ? '<td class="flight"></td>' : '') +
            (this.replay.battery ? '<td class="battery"><span class="gauge"><span class="gauge-fill">' +
                '</span></span> <span class="gauge-text num"></span></td>' : '');
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
      const reason3d = hv.View3d.unavailableReason(r);
      $('btn-3d').disabled = reason3d !== null;
      if (reason3d) $('btn-3d').title = `3D unavailable: ${reason3d}`;
      button('btn-3d', () => this.toggle3d());
      slider.addEventListener('input', () => { this.pause(); this.seek(Number(slider.value)); });
      $('speed').addEventListener('change', (e) => { this.speed = Number(e.target.value); e.target.blur(); });
      $('zoom').addEventListener('change', (e) => { this.layout(); e.target.blur(); });
      for (const name of ['footprints', 'paths', 'plans', 'targets', 'layers', 'labels', 'regions', 'truth']) {
        const box = $(`show-${name}`);
        this.show[name] = box.checked;
        box.addEventListener('change', () => {
          this.show[name] = box.checked;
          box.blur();
          if (name === 'regions' || name === 'truth') this.fillLegend();
          this.requestDraw();
        });
      }
      if (!r.owner) $('show-regions').parentElement.hidden = true;
      if (r.layerNames.length === 0) $('show-layers').parentElement.hidden = true;
      document.addEventListener('keydown', (e) => this.onKey(e));
      window.addEventListener('resize', () => this.layout());
      const overlay = $('overlay-canvas');
      overlay.addEventListener('mousemove', (e) => this.onHover(e));
      overlay.addEventListener('mouseleave', () => { this.map.hover = null; this.requestDraw(); });
      const chartCanvas = $('chart-canvas');
      const chartSeek = (e) => {
        if (!(e.buttons & 1) && e.type !== 'mousedown') return;
        const rect = chartCanvas.getBoundingClientRect();
        this.pause();
        this.seek(this.chart.timeAt(e.clientX - rect.left));
      };
      chartCanvas.addEventListener('mousedown', chartSeek);
      chartCanvas.addEventListener('mousemove', chartSeek);
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
        case 'd': case 'D': if (!$('btn-3d').disabled) this.toggle3d(); break;
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

    // The flat map or the 3D hull in the map's place; the timeline, chart and tables stay.
    toggle3d() {
      this.mode3d = !this.mode3d;
      if (this.mode3d && !this.view3d) this.view3d = new hv.View3d(this.replay, $('view3d'), this.show);
      $('map-scroll').hidden = this.mode3d;
      $('hover-info').hidden = this.mode3d;
      $('view3d').hidden = !this.mode3d;
      $('btn-3d').classList.toggle('active', this.mode3d);
      $('btn-3d').textContent = this.mode3d ? '2D' : '3D';
      this.layout();
    }

    // --- layout ---------------------------------------------------------------------------------

    layout() {
      const zoom = Number($('zoom').value);
      const avail = Math.max(100, $('map-scroll').clientWidth);
      // Fit: the whole width, cells may be a fraction of a pixel wider than others on screen.
      const pad = hv.MapView.padding;
      const cellPx = zoom > 0 ? zoom : Math.max(2, (avail - pad.left - pad.right) / this.replay.W);
      const dpr = window.devicePixelRatio || 1;
      $('map-stack').style.width = `${this.map.layout(cellPx, dpr)}px`;
      this.chart.layout(dpr);
      if (this.mode3d) {
        const width = Math.max(100, $('map-panel').clientWidth - 16);
        this.view3d.resize(width, Math.round(Math.min(0.62 * window.innerHeight, 0.5 * width)));
      }
      this.requestDraw();
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
      if (this.mode3d) this.view3d.draw();
      else this.map.draw();
      this.chart.draw();
      this.updateText();
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
        if (r.physical) {
          cells[4].textContent = !s.active ? 'failed' : !s.airborne ? 'on the ground'
              : s.away > 0 ? 'away' : 'airborne';
        }
        if (r.battery) this.showBattery(cells[5], s);
      }
      this.updateHoverInfo();
    }

    // The gauge of a battery: its seconds left, the bar's length the share of the endurance, red
    // at or below the reserve.
    showBattery(cell, s) {
      const r = this.replay;
      const step = r.trace.step_seconds || 1;
      const fill = cell.querySelector('.gauge-fill');
      const low = s.battery <= r.battery.reserve;
      fill.style.width = `${(100 * s.battery / r.battery.endurance).toFixed(1)}%`;
      fill.style.background = low ? BATTERY_LOW : BATTERY_OK;
      cell.classList.toggle('low', low);
      cell.querySelector('.gauge-text').textContent = `${+(s.battery * step).toFixed(3)} s`;
    }

    onHover(e) {
      const cell = this.map.cellAt(e.clientX, e.clientY);
      const old = this.map.hover;
      if (cell && old && cell.x === old.x && cell.y === old.y) return;
      this.map.hover = cell;
      this.requestDraw();
    }

    updateHoverInfo() {
      const info = $('hover-info');
      if (!this.map.hover) {
        info.textContent = 'Hover over a cell to see its state.';
        return;
      }
      const r = this.replay;
      const {x, y} = this.map.hover;
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
      if (r.noFly && r.noFly[i]) parts.push('no-fly position');
      if (r.unreachable && r.unreachable[i] === 1) parts.push('unreachable for close-up (only z = 2 sees it)');
      if (r.unreachable && r.unreachable[i] === 2) parts.push('unreachable (no footprint sees it)');
      const inLayers = r.layerNames.filter((name) => r.layer(name, r.t).includes(i));
      if (inLayers.length) parts.push(`layer ${inLayers.join(', ')}`);
      const fp = r.trace.footprint;
      const sight = [];
      const here = [];
      const targets = [];
      for (let k = 0; k < r.uavCount; ++k) {
        const s = r.uavState(r.t, k);
        const half = ((s.z === 1 ? fp[0] : fp[1]) - 1) / 2;
        if (s.active && s.transit === 0 && s.airborne && s.away === 0 && Math.abs(s.x - x) <= half && Math.abs(s.y - y) <= half) sight.push(k);
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

  // ---------------------------------------------------------------------------------------------
  // Start-up: the embedded trace, or a trace file chosen or dropped by the user.

  // Timings (ms since navigation) are kept for the browser test's measurements.
  const api = {ready: false, error: null, scriptAt: performance.now()};
  window.hullViewer = api;

  function start(trace) {
    const t0 = performance.now();
    try {
      const replay = new hv.Replay(trace);
      $('viewer').hidden = false;
      $('file-picker').hidden = true;
      $('load-error').hidden = true;
      const optionsText = $('view-options') ? $('view-options').textContent.trim() : '';
      const viewer = new Viewer(replay, optionsText ? JSON.parse(optionsText) : {});
      Object.assign(api, {
        // The 3D view (null while never shown) and a switch for the browser test.
        view3d: () => viewer.view3d,
        toggle3d: () => viewer.toggle3d(),
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
})(window.hullinspectViewer = window.hullinspectViewer || {});
