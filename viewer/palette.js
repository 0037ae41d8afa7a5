// Colours of the replay viewer (docs/viewer.md): cell states, partition regions, UAVs, layers.
// The browser test (viewer/test/viewer.test.mjs) checks drawn pixels against these values.
'use strict';

(function (hv) {
  // Cell colours (RGB). docs/viewer.md and the browser test use the same values.
  const COLORS = {
    nonHull: [38, 43, 51],
    unknown: [139, 147, 158],
    clean: [226, 230, 235],
    corrosion: [245, 140, 40], // M = 2, detected (seen by a UAV)
    priorOnly: [255, 196, 128], // M = 2 known only from the prior, not seen yet
    inspected: [46, 160, 67],
  };
  // Partition regions: unknown cells in the region's colour, explored cells in a light tint of it.
  // Purples, teals, pinks, olives: no blue (the footprints), no grey (unknown without regions), no
  // orange, green or light red (corrosion, inspection, frontiers); neighbours differ in hue.
  const REGION_COLORS = [
    [150, 105, 195], [40, 150, 150], [210, 100, 150], [140, 140, 45], [150, 75, 85], [60, 125, 95],
    [165, 85, 125], [175, 150, 60], [185, 120, 200], [35, 115, 125], [200, 135, 160], [120, 60, 120],
  ];
  const REGION_TINT = 0.62; // share of white mixed into a region's colour for explored cells
  // UAV k is drawn in a dark shade of region k's colour.
  const UAV_SHADE = 0.3;
  const FOOTPRINT_FILL = 'rgba(40, 120, 255, 0.22)';
  const TRUTH_MARK = 'rgb(200, 0, 0)'; // undetected corrosion with "show truth"
  const HOVER_MARK = '#ffd400';
  // No-fly positions and unreachable hull cells, hatched over the cells (map_view.js drawNoFly).
  const NO_FLY_MARK = '#111';
  const UNREACHABLE_MARK = [null, '#999', '#444']; // by kind: 1 only z = 2 sees it, 2 none does
  // The seam of a grid that closes on itself (map_view.js drawSeam): its two edges, dashed.
  const SEAM_MARK = 'rgb(230, 0, 120)';
  // The physical mission (map_view.js): launch sites, UAVs on the ground (triangles) and flying
  // between a site and the hull (diamonds); the battery gauge, green above the reserve and red at
  // or below it.
  const LAUNCH_SITE_FILL = '#f2f2f2';
  const GROUND_FILL = '#3c3c3c';
  const AWAY_FILL = '#8a8a8a';
  const BATTERY_OK = 'rgb(60, 170, 90)';
  const BATTERY_LOW = 'rgb(215, 40, 40)';
  const LAYER_COLORS = {frontiers: 'rgba(255, 105, 97, 0.62)'};
  const EXTRA_LAYER_COLORS = [
    'rgba(150, 80, 255, 0.45)', 'rgba(0, 190, 220, 0.45)', 'rgba(255, 215, 0, 0.55)',
    'rgba(255, 0, 190, 0.40)', 'rgba(120, 200, 0, 0.45)',
  ];
  const M_NAMES = ['unknown', 'clean (non-corroded, seen)', 'corrosion expected or detected',
    'corrosion inspected'];

  const rgb = (c) => `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
  const mix = (c, d, w) => c.map((v, i) => Math.round(v * (1 - w) + d[i] * w));

  function regionColor(owner) { return REGION_COLORS[owner % REGION_COLORS.length]; }
  function regionTint(owner) { return mix(regionColor(owner), [255, 255, 255], REGION_TINT); }
  function uavColor(k) { return rgb(mix(regionColor(k), [0, 0, 0], UAV_SHADE)); }
  function layerColor(name, i) {
    return LAYER_COLORS[name] || EXTRA_LAYER_COLORS[i % EXTRA_LAYER_COLORS.length];
  }

  // The colour of cell i of a replay (replay.js) at its current time, in the map and the 3D view:
  // corrosion apart by whether a UAV has seen it, unknown and clean cells in their region's colour
  // and tint when `regions` (and the trace has a partition).
  function cellColor(replay, i, regions) {
    const v = replay.map[i];
    if (v < 0) return COLORS.nonHull;
    if (v === 2) return replay.firstSeen[i] <= replay.t ? COLORS.corrosion : COLORS.priorOnly;
    if (v === 3) return COLORS.inspected;
    const o = replay.owner && regions ? replay.owner[i] : -1;
    if (o >= 0) return v === 0 ? regionColor(o) : regionTint(o);
    return v === 0 ? COLORS.unknown : COLORS.clean;
  }

  hv.palette = {
    COLORS, FOOTPRINT_FILL, TRUTH_MARK, HOVER_MARK, NO_FLY_MARK, UNREACHABLE_MARK, SEAM_MARK,
    M_NAMES, rgb,
    LAUNCH_SITE_FILL, GROUND_FILL, AWAY_FILL, BATTERY_OK, BATTERY_LOW,
    regionColor, regionTint, uavColor, layerColor, cellColor,
  };
})(window.hullinspectViewer = window.hullinspectViewer || {});
