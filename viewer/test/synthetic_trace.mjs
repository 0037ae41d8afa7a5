// A synthetic but well-formed trace (docs/trace-format.md) for load and playback measurements:
// `uavs` UAVs random-walking for `steps` steps over the hull of a real trace, sensing by the rules
// of docs/model.md §3, with an annotation for every UAV at every step and a "frontiers" layer that changes
// every step: meant as a worst case for a trace of that length.

// Small deterministic PRNG (mulberry32), so the trace is the same on every run.
export function prng(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export function syntheticTrace(base, {uavs = 8, steps = 5000, seed = 1} = {}) {
  const random = prng(seed);
  const W = base.grid.width;
  const H = base.grid.height;
  const [s1, s2] = base.footprint;
  const truth = [];
  const map = [];
  for (let y = 0; y < H; ++y) {
    for (let x = 0; x < W; ++x) {
      const t = base.truth[y][x];
      truth.push(t === '.' ? -1 : Number(t));
      const m = base.initial_map[y][x];
      map.push(m === '.' ? -1 : Number(m));
    }
  }
  const hull = truth.reduce((n, v) => n + (v >= 0 ? 1 : 0), 0);
  const corroded = truth.reduce((n, v) => n + (v === 1 ? 1 : 0), 0);
  const known = () => map.reduce((n, v) => n + (v === 1 || v === 3 ? 1 : 0), 0);
  const inspected = () => map.reduce((n, v, i) => n + (v === 3 && truth[i] === 1 ? 1 : 0), 0);

  const state = Array.from({length: uavs}, (_, k) => ({
    x: Math.floor(((k + 0.5) * W) / uavs), y: Math.floor(H / 2), z: 2, transit: 0,
  }));
  // docs/model.md §3: z = 2 sees corrosion as 2 (unless already 3) and clears clean cells to 1; z = 1
  // inspects corrosion (3) and clears clean cells.
  const sense = (changes) => {
    for (const s of state) {
      if (s.transit > 0) continue;
      const half = ((s.z === 1 ? s1 : s2) - 1) / 2;
      for (let y = Math.max(0, s.y - half); y <= Math.min(H - 1, s.y + half); ++y) {
        for (let x = Math.max(0, s.x - half); x <= Math.min(W - 1, s.x + half); ++x) {
          const i = y * W + x;
          if (truth[i] < 0) continue;
          let v;
          if (truth[i] === 0) v = 1;
          else v = s.z === 1 ? 3 : map[i] === 3 ? 3 : 2;
          if (map[i] !== v) {
            map[i] = v;
            changes.set(i, v);
          }
        }
      }
    }
  };
  const frontiers = () => {
    const out = [];
    for (let y = 0; y < H; ++y) {
      for (let x = 0; x < W; ++x) {
        const i = y * W + x;
        if (map[i] !== 0) continue;
        if ((x > 0 && map[i - 1] > 0) || (x + 1 < W && map[i + 1] > 0) ||
            (y > 0 && map[i - W] > 0) || (y + 1 < H && map[i + W] > 0)) {
          out.push(i);
        }
      }
    }
    return out;
  };
  const modes = ['explore', 'inspect', 'transit'];
  const randomCell = () => [Math.floor(random() * W), Math.floor(random() * H)];

  const frames = [];
  const series = {inspected: [], known: []};
  let tc = null;
  let tm = null;
  let moves = 0;
  let planeChanges = 0;
  let hovers = 0;
  for (let t = 0; t <= steps; ++t) {
    if (t > 0) {
      for (const s of state) {
        if (s.transit > 0) {
          if (--s.transit === 0) s.z = 3 - s.z;
          continue;
        }
        const r = random();
        if (r < 0.03) {
          // The model's plane change: u_z steps, the first of which leaves u_z - 1 to go.
          s.transit = base.plane_change_steps - 1;
          ++planeChanges;
          if (s.transit === 0) s.z = 3 - s.z;
        } else if (r < 0.08) {
          ++hovers;
        } else {
          const [dx, dy] = [[1, 0], [-1, 0], [0, 1], [0, -1]][Math.floor(random() * 4)];
          s.x = Math.max(0, Math.min(W - 1, s.x + dx));
          s.y = Math.max(0, Math.min(H - 1, s.y + dy));
          ++moves;
        }
      }
    }
    const changes = new Map();
    sense(changes);
    const frame = {t, u: [], c: []};
    for (const s of state) frame.u.push(s.x, s.y, s.z, s.transit, 1);
    for (const [i, v] of changes) frame.c.push(i, v);
    frame.p = {};
    for (let k = 0; k < uavs; ++k) {
      frame.p[String(k)] = {
        mode: modes[(k + Math.floor(t / 50)) % modes.length],
        target: randomCell(),
        plan: Array.from({length: 6}, randomCell),
      };
    }
    frame.l = {frontiers: frontiers()};
    frames.push(frame);
    const c = inspected();
    const m = known();
    series.inspected.push(c);
    series.known.push(m);
    if (tc === null && c === corroded) tc = t;
    if (tm === null && m === hull) tm = t;
  }
  // Frame 0 of a real trace holds the changes of t = 0's sensing relative to initial_map, which is
  // exactly what was recorded above.
  return {
    format: 'hullinspect-trace',
    version: 1,
    generator: 'viewer/test/synthetic_trace.mjs',
    parameters: {algorithm: 'synthetic random walk', uavs, seed, s1, s2},
    grid: base.grid,
    plane_change_steps: base.plane_change_steps,
    footprint: base.footprint,
    truth: base.truth,
    prior: base.prior,
    initial_map: base.initial_map,
    partition: null,
    uav_fields: ['x', 'y', 'z', 'transit_left', 'active'],
    frames,
    series,
    result: {
      complete: tm !== null, T_c: tc, T_m: tm, steps, hull_cells: hull, corroded_cells: corroded,
      moves, plane_changes: planeChanges, hovers, redundant_observations: 0,
    },
  };
}

// The map M at time t rebuilt the slow, obvious way: initial_map plus every change up to t.
export function mapAt(trace, t) {
  const W = trace.grid.width;
  const map = [];
  for (const row of trace.initial_map) for (const ch of row) map.push(ch === '.' ? -1 : Number(ch));
  for (let i = 0; i <= t; ++i) {
    const c = trace.frames[i].c;
    for (let j = 0; j < c.length; j += 2) map[c[j]] = c[j + 1];
  }
  return {map, W, H: trace.grid.height};
}
