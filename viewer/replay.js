// The replay model (docs/viewer.md): everything derived from a trace (docs/trace-format.md) once,
// and the mission state at the current time.
//
// State at time t is rebuilt from keyframes + deltas: the map M is copied every KEYFRAME_INTERVAL
// frames while loading, and a seek restores the nearest keyframe at or before t and applies the
// cell changes of the frames after it (at most KEYFRAME_INTERVAL - 1 of them). Planner annotations,
// which traces record only when they change, are found by binary search. Layers are recorded as
// whole sets or as changes ({add, remove}, trace version 2) with a whole set at least every 128
// frames: a layer at time t is its last whole set at or before t plus the changes after it, kept
// per layer and moved forward incrementally while playing.
'use strict';

(function (hv) {
  const KEYFRAME_INTERVAL = 128;

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

  class Replay {
    constructor(trace) {
      if (!trace || trace.format !== 'hullinspect-trace') throw new Error('not a hullinspect trace');
      // Version 1 is version 2 without layer changes; version 2 is version 3 of the paper's model;
      // version 3 is version 4 with a flight home's climb recorded one step late.
      if (![1, 2, 3, 4].includes(trace.version)) {
        throw new Error(`trace version ${trace.version} is not supported`);
      }
      this.trace = trace;
      this.W = trace.grid.width;
      this.H = trace.grid.height;
      this.frameCount = trace.frames.length;
      this.lastT = this.frameCount - 1;
      // Values per UAV: x, y, z, transit_left, active, and with launch sites airborne,
      // battery_left, away_left (docs/trace-format.md).
      this.fields = trace.uav_fields ? trace.uav_fields.length : 5;
      this.physical = this.fields >= 8;
      this.uavCount = trace.frames[0].u.length / this.fields;
      // The battery in steps (endurance, reserve), or null when flight is unlimited.
      this.battery = trace.battery ? {endurance: trace.battery.endurance_steps,
                                      reserve: trace.battery.reserve_steps} : null;
      this.launchSites = trace.launch ? trace.launch.sites : [];
      this.truth = this.parseRows(trace.truth);
      this.prior = this.parseRows(trace.prior);
      this.owner = trace.partition ? this.parseRows(trace.partition, true) : null;
      // No-fly zones (docs/model.md): '#' no-fly positions; 'd' hull cells only z = 2 sees, 'x'
      // hull cells no footprint sees. Both absent from traces without no-fly zones.
      this.noFly = trace.no_fly ? this.parseSymbols(trace.no_fly, {'#': 1}) : null;
      this.unreachable = trace.unreachable ? this.parseSymbols(trace.unreachable, {d: 1, x: 2}) : null;
      this.indexChanges();
      this.indexUavs();
      this.indexFirstSeen();
      this.indexAnnotations();
      this.buildKeyframes();
      this.t = this.lastT;
      this.seek(0);
    }

    // rows[y] strings (y = 0 bottom) → Int8Array by flat index y * W + x; symbols → values, else 0.
    parseSymbols(rows, values) {
      const out = new Int8Array(this.W * this.H);
      for (let y = 0; y < this.H; ++y) {
        for (let x = 0; x < this.W; ++x) out[y * this.W + x] = values[rows[y][x]] || 0;
      }
      return out;
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

    // UAV states of every frame: `fields` values per UAV.
    indexUavs() {
      const stride = this.uavCount * this.fields;
      this.uav = new Int32Array(this.frameCount * stride);
      this.trace.frames.forEach((f, i) => this.uav.set(f.u, i * stride));
    }

    // The first time each cell was in a sensing footprint (any UAV, any plane), or Infinity: so
    // corrosion known only from the prior (M = 2, not seen yet) is told from detected corrosion.
    indexFirstSeen() {
      const fp = this.trace.footprint;
      const seen = new Float64Array(this.W * this.H).fill(Infinity);
      const f = this.fields;
      const stride = this.uavCount * f;
      const u = this.uav;
      for (let t = 0; t < this.frameCount; ++t) {
        for (let o = t * stride; o < (t + 1) * stride; o += f) {
          // Failed, changing plane or away from the hull: no sensing.
          if (u[o + 4] !== 1 || u[o + 3] !== 0 || (f >= 8 && u[o + 7] !== 0)) continue;
          const half = ((u[o + 2] === 1 ? fp[0] : fp[1]) - 1) / 2;
          const y0 = Math.max(0, u[o + 1] - half);
          const y1 = Math.min(this.H - 1, u[o + 1] + half);
          const x0 = Math.max(0, u[o] - half);
          const x1 = Math.min(this.W - 1, u[o] + half);
          for (let y = y0; y <= y1; ++y) {
            for (let i = y * this.W + x0; i <= y * this.W + x1; ++i)
              if (seen[i] > t) seen[i] = t;
          }
        }
      }
      this.firstSeen = seen;
    }

    uavState(t, k) {
      const o = (t * this.uavCount + k) * this.fields;
      const u = this.uav;
      // Without launch sites a UAV is always airborne, on the hull, with an unlimited battery.
      const physical = this.physical;
      return {x: u[o], y: u[o + 1], z: u[o + 2], transit: u[o + 3], active: u[o + 4] === 1,
              airborne: !physical || u[o + 5] === 1, battery: physical ? u[o + 6] : -1,
              away: physical ? u[o + 7] : 0};
    }

    // Per UAV and per layer: the frames where the annotation changed, for binary search.
    indexAnnotations() {
      this.annotationTimes = Array.from({length: this.uavCount}, () => []);
      this.annotations = Array.from({length: this.uavCount}, () => []);
      this.layerNames = [];
      this.layerTimes = {};
      this.layerCells = {};
      this.layerFull = {};   // per change: the index of the last whole set at or before it
      this.layerState = {};  // per layer: {i, set, cells} of the last lookup
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
              this.layerFull[name] = [];
            }
            const v = f.l[name];
            const full = Array.isArray(v);
            const times = this.layerTimes[name];
            const fulls = this.layerFull[name];
            if (!full && fulls.length === 0)
              throw new Error(`frames[${t}].l.${name}: changes before a whole set`);
            fulls.push(full ? times.length : fulls[fulls.length - 1]);
            times.push(t);
            this.layerCells[name].push(v);
          }
        }
      });
      this.layerNames.sort((a, b) => (a === 'frontiers' ? -1 : b === 'frontiers' ? 1 : a < b ? -1 : 1));
    }

    annotation(k, t) {
      const i = lastAtOrBefore(this.annotationTimes[k], t);
      return i < 0 ? null : this.annotations[k][i];
    }

    // The cells of layer `name` at time t (an array; the same array while the layer is unchanged).
    layer(name, t) {
      const i = lastAtOrBefore(this.layerTimes[name], t);
      if (i < 0) return [];
      const entries = this.layerCells[name];
      if (Array.isArray(entries[i])) return entries[i];
      let state = this.layerState[name];
      const key = this.layerFull[name][i];
      if (!state || state.i > i || state.i < key) {
        state = {i: key, set: new Set(entries[key]), cells: null};
      }
      for (let j = state.i + 1; j <= i; ++j) {
        const e = entries[j];
        if (Array.isArray(e)) {
          state.set = new Set(e);
          continue;
        }
        if (e.remove)
          for (const c of e.remove) state.set.delete(c);
        if (e.add)
          for (const c of e.add) state.set.add(c);
      }
      if (state.i !== i || !state.cells) state.cells = Array.from(state.set);
      state.i = i;
      this.layerState[name] = state;
      return state.cells;
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

  hv.Replay = Replay;
})(window.hullinspectViewer = window.hullinspectViewer || {});
