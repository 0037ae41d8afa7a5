// Browser test of the replay viewer's 3D view: Debian's Chromium (WebGL by its software renderer)
// driven by playwright-core, no network. Run by CTest as `viewer_browser_3d`, or by hand:
//   HULLINSPECT_CLI=build/release/hullinspect node --test viewer/test/viewer3d.test.mjs
// Screenshots go to $HULLINSPECT_TEST_OUTPUT (default: a new temporary folder).

import {after, before, test} from 'node:test';
import assert from 'node:assert/strict';
import {spawnSync} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import {Browser, settle} from './browser.mjs';
import {mapAt} from './synthetic_trace.mjs';

const CLI = process.env.HULLINSPECT_CLI;
const OUT = process.env.HULLINSPECT_TEST_OUTPUT ||
    fs.mkdtempSync(path.join(os.tmpdir(), 'hullinspect-viewer3d-test-'));

// The viewer's colours (viewer/palette.js, docs/viewer.md), written out again on purpose.
const BACKGROUND = [245, 246, 248];
const INSPECTED = [46, 160, 67];
const REGIONS = [
  [150, 105, 195], [40, 150, 150], [210, 100, 150], [140, 140, 45], [150, 75, 85], [60, 125, 95],
  [165, 85, 125], [175, 150, 60], [185, 120, 200], [35, 115, 125], [200, 135, 160], [120, 60, 120],
];
const tint = (c) => c.map((v) => Math.round(v * (1 - 0.62) + 255 * 0.62));
const shade = (c) => c.map((v) => Math.round(v * (1 - 0.3)));

// WebGL without a GPU: Chromium's SwiftShader.
const BROWSER_ARGS = [
  '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-quic',
  '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync',
];

let browser;
let dtc; // {trace, html, plainHtml}
let mask; // {trace, html}

function cli(args) {
  return spawnSync(CLI, args, {encoding: 'utf8'});
}

before(async () => {
  assert.ok(CLI, 'set HULLINSPECT_CLI to the hullinspect binary (CTest does)');
  fs.mkdirSync(OUT, {recursive: true});
  // 16 UAVs on the DTC container ship (a hull imported from a mesh), lawnmower (regions).
  const tracePath = path.join(OUT, 'dtc-16.json');
  let r = cli(['run', '--hull', 'dtc', '--uavs', '16', '--seed', '3', '--trace', tracePath]);
  assert.equal(r.status, 0, r.stderr);
  const html = path.join(OUT, 'dtc-16-3d.html');
  r = cli(['view', tracePath, '--3d', '--out', html]);
  assert.equal(r.status, 0, r.stderr);
  const plainHtml = path.join(OUT, 'dtc-16.html');
  r = cli(['view', tracePath, '--out', plainHtml]);
  assert.equal(r.status, 0, r.stderr);
  dtc = {trace: JSON.parse(fs.readFileSync(tracePath, 'utf8')), html, plainHtml};
  // A mission on the default mask hull: no 3D geometry.
  const maskTrace = path.join(OUT, 'mask-4.json');
  r = cli(['run', '--uavs', '4', '--seed', '3', '--trace', maskTrace]);
  assert.equal(r.status, 0, r.stderr);
  const maskHtml = path.join(OUT, 'mask-4.html');
  r = cli(['view', maskTrace, '--out', maskHtml]);
  assert.equal(r.status, 0, r.stderr);
  mask = {trace: maskTrace, html: maskHtml};

  browser = await Browser.launch(BROWSER_ARGS);
});

after(async () => {
  if (browser) await browser.close();
});

const open = (file) => browser.open(file);

// The 3D canvas's pixels: how many differ from the background, and the colour at given points.
async function canvasPixels(page, points = []) {
  return page.evaluate((points) => {
    const source = window.hullViewer.view3d().renderer.domElement;
    const c = document.createElement('canvas');
    c.width = source.width;
    c.height = source.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(source, 0, 0);
    const data = ctx.getImageData(0, 0, c.width, c.height).data;
    let drawn = 0;
    for (let p = 0; p < data.length; p += 4) {
      if (Math.abs(data[p] - 245) + Math.abs(data[p + 1] - 246) + Math.abs(data[p + 2] - 248) > 6) ++drawn;
    }
    const at = points.map(([x, y]) => {
      const p = (Math.round(y) * c.width + Math.round(x)) * 4;
      return [data[p], data[p + 1], data[p + 2]];
    });
    return {drawn, total: c.width * c.height, at, width: c.width, height: c.height};
  }, points);
}

// Screen pixel of each ship-frame point in the 3D view, and whether the hull hides it (the first
// surface a ray from the camera meets is more than 5 cm before it).
async function project(page, points) {
  return page.evaluate((points) => {
    const v = window.hullViewer.view3d();
    const canvas = v.renderer.domElement;
    const ray = new THREE_VIEW.Raycaster();
    return points.map((p) => {
      const point = new THREE_VIEW.Vector3(...p);
      const q = point.clone().project(v.camera);
      ray.setFromCamera({x: q.x, y: q.y}, v.camera);
      const hit = ray.intersectObject(v.hullMesh)[0];
      const hidden = hit !== undefined && hit.distance < v.camera.position.distanceTo(point) - 0.05;
      return [(q.x + 1) / 2 * canvas.width, (1 - q.y) / 2 * canvas.height, hidden];
    });
  }, points);
}

test('a mesh hull opens in 3D with view --3d, loads nothing, and toggles to 2D and back', async () => {
  const {page, requests} = await open(dtc.html);
  assert.deepEqual(requests.filter((u) => !u.startsWith('file:')), []);
  assert.equal(await page.isVisible('#view3d canvas'), true);
  assert.equal(await page.isVisible('#grid-canvas'), false);
  assert.equal(await page.textContent('#btn-3d'), '2D');
  await page.click('#btn-3d');
  assert.equal(await page.isVisible('#grid-canvas'), true);
  assert.equal(await page.isVisible('#view3d'), false);
  await page.keyboard.press('d');
  await settle(page);
  assert.equal(await page.isVisible('#view3d canvas'), true);
  await page.close();
  // Without --3d the same page opens in 2D and offers 3D.
  const plain = (await open(dtc.plainHtml)).page;
  assert.equal(await plain.isVisible('#grid-canvas'), true);
  assert.equal(await plain.isEnabled('#btn-3d'), true);
  await plain.close();
});

test('a mask hull: 3D disabled with its reason, three.js not inlined, view --3d refused', async () => {
  const {page} = await open(mask.html);
  assert.equal(await page.isEnabled('#btn-3d'), false);
  assert.match(await page.getAttribute('#btn-3d', 'title'), /3D unavailable: .*imported from a mesh/);
  assert.equal(await page.evaluate(() => typeof THREE_VIEW), 'undefined');
  await page.close();
  const out = path.join(OUT, 'mask-3d.html');
  const r = cli(['view', mask.trace, '--3d', '--out', out]);
  assert.equal(r.status, 2);
  assert.equal(r.stderr.trim().split('\n').length, 1);
  assert.match(r.stderr, /--3d: .* mask hull without 3D geometry/);
  assert.equal(fs.existsSync(out), false);
  // What three.js adds to a page with 3D geometry: the mesh hull's page against its trace.
  const added = fs.statSync(dtc.html).size - fs.statSync(mask.html).size;
  assert.ok(added > 300e3, `a 3D page is only ${added} bytes larger`);
});

// Cells whose 5 × 5 neighbourhood has the same colour at time t and `faces` the camera (not seen
// at a grazing angle), so no pixel blends two colours, away from every UAV: M = 0 in its
// region's colour, M = 1 in its tint, M = 3 inspected (non-hull and M = 2 cells are left out);
// `away`: how many cells from every UAV (its sphere and sight line cover the hull near it).
function uniformCells(trace, t, faces, step = 23, away = 12) {
  const W = trace.grid.width;
  const H = trace.grid.height;
  const owner = (x, y) => {
    const ch = trace.partition[y][x];
    return ch >= 'A' ? ch.charCodeAt(0) - 55 : Number(ch);
  };
  const {map} = mapAt(trace, t);
  const expected = (x, y) => {
    const v = map[y * W + x];
    const region = REGIONS[owner(x, y) % REGIONS.length];
    return v === 0 ? region : v === 1 ? tint(region) : v === 3 ? INSPECTED : null;
  };
  const u = trace.frames[t].u;
  const cells = [];
  for (let y = 4; y < H - 4; y += 5) {
    for (let x = 4 + (y % 3); x < W - 4; x += step) {
      const c = expected(x, y);
      let ok = c !== null;
      for (let dy = -2; dy <= 2 && ok; ++dy) {
        for (let dx = -2; dx <= 2 && ok; ++dx) {
          const d = expected(x + dx, y + dy);
          ok = d !== null && d.every((v, j) => v === c[j]) && faces(x + dx, y + dy);
        }
      }
      for (let o = 0; o < u.length && ok; o += 5) ok = Math.abs(u[o] - x) > away || Math.abs(u[o + 1] - y) > away;
      if (ok) cells.push({x, y, color: c, state: map[y * W + x]});
    }
  }
  return cells;
}

test('the hull is drawn in the colours of M at the replay time, the UAVs in theirs', async () => {
  const {page} = await open(dtc.html);
  const trace = dtc.trace;
  const {origin, side_plane_y: ys, depth} = trace.ship_frame;
  const cell = trace.grid.cell_size_m;
  const surface = (x, y) => [origin[0] + (x + 0.5) * cell, ys - depth[y][x], origin[1] + (y + 0.5) * cell];
  await page.uncheck('#show-footprints');
  await page.uncheck('#show-paths');
  await page.uncheck('#show-labels');
  const normal = trace.ship_frame.normal;
  const faces = (x, y) => normal[y][x][1] < -0.9; // the side, not the bilge
  for (const t of [0, 300, trace.frames.length - 1]) {
    await page.evaluate((t) => window.hullViewer.seek(t), t);
    await settle(page);
    const candidates = uniformCells(trace, t, faces);
    const projected = await project(page, candidates.map(({x, y}) => surface(x, y)));
    const cells = candidates.filter((c, j) => !projected[j][2]);
    assert.ok(cells.length >= 20, `only ${cells.length} cells to check at t = ${t}`);
    const pixels = await canvasPixels(page, projected.filter((p) => !p[2]));
    cells.forEach(({x, y, color, state}, j) => {
      assert.deepEqual(pixels.at[j], color, `cell (${x}, ${y}) at t = ${t}, M = ${state}`);
    });
    // The hull fills a good part of the view; the background the rest.
    assert.ok(pixels.drawn > 0.1 * pixels.total && pixels.drawn < 0.7 * pixels.total,
              `${pixels.drawn} of ${pixels.total} pixels drawn at t = ${t}`);
    // The states checked: at t = 0 unknown cells, at the end none.
    const states = new Set(cells.map((c) => c.state));
    if (t === 0) assert.ok(states.has(0));
    if (t === trace.frames.length - 1) assert.ok(!states.has(0) && states.has(1), [...states].join());
  }
  // Each UAV at its stand-off position, in the dark shade of its region's colour.
  const t = 300;
  await page.evaluate((t) => window.hullViewer.seek(t), t);
  await settle(page);
  const u = trace.frames[t].u;
  const theta = (trace.camera.theta_deg * Math.PI) / 180;
  const uavPoints = [];
  for (let o = 0; o < u.length; o += 5) {
    const [x, y, z] = [u[o], u[o + 1], u[o + 2]];
    const zeta = (trace.footprint[z - 1] * cell) / (2 * Math.tan(theta / 2));
    const p = surface(x, y);
    uavPoints.push([p[0], p[1] - zeta, p[2]]);
  }
  const pixels = await canvasPixels(page, await project(page, uavPoints));
  pixels.at.forEach((got, k) => assert.deepEqual(got, shade(REGIONS[k % REGIONS.length]), `UAV ${k} at t = ${t}`));
  await page.close();
});

test('zooming with the wheel brings the hull closer, dragging orbits it', async () => {
  const {page} = await open(dtc.html);
  const box = await page.locator('#view3d canvas').boundingBox();
  const before = await canvasPixels(page);
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  for (let i = 0; i < 5; ++i) await page.mouse.wheel(0, -200);
  await page.waitForTimeout(300);
  const zoomed = await canvasPixels(page);
  assert.ok(zoomed.drawn > 1.3 * before.drawn, `${before.drawn} → ${zoomed.drawn} pixels drawn`);
  const camera = () => page.evaluate(() => window.hullViewer.view3d().camera.position.toArray());
  const from = await camera();
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 200, box.y + box.height / 2 + 50, {steps: 5});
  await page.mouse.up();
  const to = await camera();
  assert.ok(Math.hypot(...from.map((v, i) => v - to[i])) > 1, `camera ${from} → ${to}`);
  await page.close();
});

test('the 16 UAVs\' labels on the DTC hull never cover one another', async () => {
  const {page} = await open(dtc.html);
  const last = dtc.trace.frames.length - 1;
  const result = await page.evaluate((last) => {
    const v = window.hullViewer.view3d();
    const problems = [];
    let labels = 0;
    for (let t = 0; t <= last; t += 20) {
      window.hullViewer.seek(t);
      v.draw();
      const boxes = v.labelBoxes;
      labels += boxes.length;
      if (boxes.length !== 16) problems.push(`t = ${t}: ${boxes.length} labels`);
      boxes.forEach((b, i) => {
        for (const o of boxes.slice(0, i)) {
          if (b.x < o.x + o.w && o.x < b.x + b.w && b.y < o.y + o.h && o.y < b.y + b.h) {
            problems.push(`t = ${t}: labels of UAV ${b.k} and ${o.k} overlap`);
          }
        }
      });
    }
    return {problems, labels};
  }, last);
  assert.deepEqual(result.problems, []);
  assert.ok(result.labels >= 16 * 40);
  await page.close();
});

// What the screenshot shows, apart from the background: a good part of the view.
async function screenshot(page, name) {
  const pixels = await canvasPixels(page);
  assert.ok(pixels.drawn > 0.05 * pixels.total, `${name}: ${pixels.drawn} of ${pixels.total} pixels drawn`);
  await page.locator('#map-panel').screenshot({path: path.join(OUT, `${name}.png`)});
}

test('screenshot of 16 UAVs on the DTC hull in 3D', async () => {
  const {page} = await open(dtc.html);
  await page.evaluate(() => window.hullViewer.seek(300));
  await settle(page);
  await screenshot(page, 'viewer-3d-dtc-16');
  await page.close();
});

// A mission on the Wigley hull of docs/hulls.md (100 m × 8 m, 200 × 16 cells of 0.5 m), written
// as a 3D page; `extra` are more `run` arguments.
function wigleyPage(name, extra = []) {
  const stl = path.join(OUT, 'wigley.stl');
  if (!fs.existsSync(stl)) {
    const tool = path.join(path.dirname(new URL(import.meta.url).pathname), '../../tools/make_wigley_hull.py');
    const r = spawnSync('/usr/bin/python3', [tool, stl, '--length', '100', '--beam', '10', '--draft', '8'],
                        {encoding: 'utf8'});
    assert.equal(r.status, 0, r.stderr);
  }
  const trace = path.join(OUT, `${name}.json`);
  let r = cli(['run', '--hull', stl, '--uavs', '16', '--seed', '3', '--trace', trace, ...extra]);
  assert.equal(r.status, 0, r.stderr);
  const html = path.join(OUT, `${name}.html`);
  r = cli(['view', trace, '--3d', '--out', html]);
  assert.equal(r.status, 0, r.stderr);
  return {html, trace: JSON.parse(fs.readFileSync(trace, 'utf8'))};
}

// The picture in docs/viewer.md: a hull the repository may show (the DTC data is GPL-3+), the
// Wigley hull, 16 UAVs, footprints and paths at t = 30 s.
test('screenshot of 16 UAVs on a Wigley hull in 3D', async () => {
  const {page} = await open(wigleyPage('wigley-16').html);
  await page.evaluate(() => window.hullViewer.seek(30));
  await settle(page);
  await screenshot(page, 'viewer-3d-wigley-16');
  await page.close();
});

// The unrolled Wigley hull (both sides and the bow in one grid, 404 × 16 cells of 0.5 m): each cell
// at its own surface point, the UAVs at their stand-off along the cell's normal.
test('an unrolled hull in 3D: cells at their surface points, UAVs along the normals', async () => {
  const {html, trace} = wigleyPage('wigley-both-16', ['--sides', 'both']);
  assert.equal(trace.ship_frame.side, 'both');
  const {page} = await open(html);
  await page.uncheck('#show-footprints');
  await page.uncheck('#show-paths');
  await page.uncheck('#show-labels');
  const {surface, normal} = trace.ship_frame;
  const eye = await page.evaluate(() => {
    const v = window.hullViewer.view3d();
    return [v.camera.position.toArray(), v.controls.target.toArray()];
  });
  const view = eye[0].map((v, d) => v - eye[1][d]);
  const length = Math.hypot(...view);
  // Facing the camera: the normal within 60° of the direction to the camera.
  const faces = (x, y) => normal[y][x].reduce((sum, v, d) => sum + v * view[d], 0) > 0.5 * length;
  let sides = new Set();
  for (const t of [0, 30, trace.frames.length - 1]) {
    await page.evaluate((t) => window.hullViewer.seek(t), t);
    await settle(page);
    // The hull alone: the UAVs and their sight lines hidden for this picture.
    await page.evaluate(() => {
      const v = window.hullViewer.view3d();
      for (const u of v.uavs) u.mesh.visible = u.sight.visible = false;
      v.render();
    });
    const candidates = uniformCells(trace, t, faces, 3, -1);
    const projected = await project(page, candidates.map(({x, y}) => surface[y][x]));
    const cells = candidates.filter((c, j) => !projected[j][2]);
    assert.ok(cells.length >= 5, `only ${cells.length} cells to check at t = ${t}`);
    const pixels = await canvasPixels(page, projected.filter((p) => !p[2]));
    cells.forEach(({x, y, color, state}, j) => {
      assert.deepEqual(pixels.at[j], color, `cell (${x}, ${y}) at t = ${t}, M = ${state}`);
      sides.add(surface[y][x][0] > 45 ? 'bow' : surface[y][x][1] < 0 ? 'starboard' : 'port');
    });
  }
  // The camera sees starboard and the bow of the unrolled grid.
  assert.ok(sides.has('starboard') && sides.has('bow'), [...sides].join());
  // Each UAV that the hull does not hide: at S + ζ·n of its cell, in its region's dark shade.
  const t = 30;
  await page.evaluate((t) => {
    window.hullViewer.seek(t);
    const v = window.hullViewer.view3d();
    for (const u of v.uavs) u.mesh.visible = true;
    v.draw();
  }, t);
  await settle(page);
  const u = trace.frames[t].u;
  const cell = trace.grid.cell_size_m;
  const theta = (trace.camera.theta_deg * Math.PI) / 180;
  const uavPoints = [];
  for (let o = 0; o < u.length; o += 5) {
    const [x, y, z] = [u[o], u[o + 1], u[o + 2]];
    const zeta = (trace.footprint[z - 1] * cell) / (2 * Math.tan(theta / 2));
    uavPoints.push(surface[y][x].map((v, d) => v + zeta * normal[y][x][d]));
  }
  const at = await project(page, uavPoints);
  const pixels = await canvasPixels(page, at);
  let seen = 0;
  pixels.at.forEach((got, k) => {
    if (at[k][2]) return; // behind the hull
    assert.deepEqual(got, shade(REGIONS[k % REGIONS.length]), `UAV ${k} at t = ${t}`);
    ++seen;
  });
  assert.ok(seen >= 4, `only ${seen} UAVs in view`);
  // The picture in docs/hulls.md: with footprints, paths and labels.
  for (const box of ['#show-footprints', '#show-paths', '#show-labels']) await page.check(box);
  await settle(page);
  await screenshot(page, 'viewer-3d-wigley-both-16');
  await page.close();
});

test('no-fly positions darken the view exactly where they are', async () => {
  const {html, trace} = wigleyPage('wigley-no-fly', ['--no-fly-box', '90,4,100,10']);
  const {page} = await open(html);
  await page.uncheck('#show-labels');
  await page.uncheck('#show-paths');
  await page.uncheck('#show-footprints');
  const W = trace.grid.width;
  const noFly = trace.no_fly.join('');
  assert.equal([...noFly].filter((c) => c === '#').length, 11 * 7);
  assert.equal(await page.evaluate(() => window.hullViewer.view3d().noFly.geometry.attributes.position.count),
               11 * 7 * 6);
  // Each cell's point out at the close-up stand-off, seen with and without the no-fly tiles.
  const {origin, side_plane_y: ys, depth} = trace.ship_frame;
  const cell = trace.grid.cell_size_m;
  const zeta1 = (trace.footprint[0] * cell) / (2 * Math.tan((trace.camera.theta_deg * Math.PI) / 360));
  const cells = [[95, 7], [93, 6], [98, 8], [40, 7], [150, 8], [95, 14]];
  const points = cells.map(([x, y]) => [origin[0] + (x + 0.5) * cell, ys - depth[y][x] - zeta1,
    origin[1] + (y + 0.5) * cell]);
  const at = await project(page, points);
  const shown = (await canvasPixels(page, at)).at;
  await page.evaluate(() => { const v = window.hullViewer.view3d(); v.noFly.visible = false; v.render(); });
  const hidden = (await canvasPixels(page, at)).at;
  cells.forEach(([x, y], j) => {
    const inside = noFly[y * W + x] === '#';
    const darker = shown[j].every((v, d) => v < 0.8 * hidden[j][d]);
    assert.equal(darker, inside, `cell (${x}, ${y}): ${shown[j]} with the no-fly tiles, ${hidden[j]} without`);
  });
  await page.close();
});

// The Wigley hull closed at its stern (--include transom): column 0 and column W − 1 meet at the
// seam. The 2D map dashes both edges of the grid in the seam's colour; the 3D view draws the seam
// as one line on the hull, along the stern's centre line where the two ends meet.
test('the seam is marked on both edges of the 2D map and as one line on the hull in 3D', async () => {
  const SEAM = [230, 0, 120]; // viewer/palette.js SEAM_MARK, written out again on purpose
  const {html, trace} = wigleyPage('wigley-seam-16', ['--sides', 'both', '--include', 'transom']);
  assert.equal(trace.ship_frame.seam, true);
  const {width: W, height: H, cell_size_m: cell} = trace.grid;
  const {surface} = trace.ship_frame;
  assert.ok(Math.hypot(...surface[0][0].map((v, d) => v - surface[0][W - 1][d])) < cell,
            'the two ends of a row meet at the seam');
  const {page} = await open(html);
  // 3D: one point per row, between the row's two ends (the seam), a tenth of a cell off them.
  const seam = await page.evaluate(() => window.hullViewer.view3d().seamPoints);
  assert.equal(seam.length, H);
  seam.forEach((p, y) => {
    for (const q of [surface[y][0], surface[y][W - 1]]) {
      const gap = Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
      assert.ok(gap <= 0.6 * cell, `row ${y}: seam point ${p} is ${gap} m from its end ${q}`);
    }
  });
  // 2D: both edges dashed in the seam's colour, nothing else drawn there.
  await page.click('#btn-3d');
  await page.evaluate(() => {
    for (const name of ['footprints', 'paths', 'plans', 'targets', 'layers', 'labels']) {
      const box = document.getElementById(`show-${name}`);
      box.checked = false;
      box.dispatchEvent(new Event('change'));
    }
  });
  await settle(page);
  const {edges, pixels} = await page.evaluate(() => {
    const map = window.hullViewer.viewer.map;
    const c = document.getElementById('overlay-canvas');
    const dpr = c.width / c.getBoundingClientRect().width;
    const ctx = c.getContext('2d');
    const at = (x, y) => Array.from(ctx.getImageData(Math.floor(x * dpr), Math.floor(y * dpr), 1, 1).data);
    // 18 px: the map's top padding; the first dash covers its first 6 px.
    return {edges: map.seamEdges, pixels: map.seamEdges.map((x) => at(x, 18 + 3))};
  });
  assert.equal(edges.length, 2);
  pixels.forEach((p, j) => assert.deepEqual(p.slice(0, 3), SEAM, `edge ${j}: ${p}`));
  await page.close();
  // A hull that does not close on itself has no seam to mark.
  const plain = await open(mask.html);
  assert.deepEqual(await plain.page.evaluate(() => window.hullViewer.viewer.map.seamEdges), []);
  await plain.page.close();
});
