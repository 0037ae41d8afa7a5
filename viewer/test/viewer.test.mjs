// Browser test of the replay viewer: Debian's Chromium driven by playwright-core, no network.
// Run by CTest as `viewer_browser` (HULLINSPECT_CLI = the built CLI), or by hand:
//   HULLINSPECT_CLI=build/release/hullinspect node --test viewer/test/viewer.test.mjs
// Screenshots and measurements go to $HULLINSPECT_TEST_OUTPUT (default: a new temporary folder).

import {after, before, test} from 'node:test';
import assert from 'node:assert/strict';
import {execFileSync, spawnSync} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import {Browser, settle} from './browser.mjs';
import {mapAt, prng, syntheticTrace} from './synthetic_trace.mjs';

const CLI = process.env.HULLINSPECT_CLI;
const OUT = process.env.HULLINSPECT_TEST_OUTPUT ||
    fs.mkdtempSync(path.join(os.tmpdir(), 'hullinspect-viewer-test-'));

// The viewer's colours (viewer/viewer.js, docs/viewer.md), written out again on purpose.
const NON_HULL = [38, 43, 51];
const UNKNOWN = [139, 147, 158];
const CLEAN = [226, 230, 235];
const CORROSION = [245, 140, 40];
const PRIOR_ONLY = [255, 196, 128];
const INSPECTED = [46, 160, 67];
const REGIONS = [
  [150, 105, 195], [40, 150, 150], [210, 100, 150], [140, 140, 45], [150, 75, 85], [60, 125, 95],
  [165, 85, 125], [175, 150, 60], [185, 120, 200], [35, 115, 125], [200, 135, 160], [120, 60, 120],
];
const tint = (c) => c.map((v) => Math.round(v * (1 - 0.62) + 255 * 0.62));

// Cells some UAV has sensed at or before t (footprints of UAVs on a plane), written out again.
function seenBy(trace, t) {
  const W = trace.grid.width;
  const H = trace.grid.height;
  const seen = new Uint8Array(W * H);
  for (let i = 0; i <= t; ++i) {
    const u = trace.frames[i].u;
    for (let o = 0; o < u.length; o += 5) {
      const [x, y, z, transit, active] = u.slice(o, o + 5);
      if (!active || transit) continue;
      const half = (trace.footprint[z - 1] - 1) / 2;
      for (let yy = Math.max(0, y - half); yy <= Math.min(H - 1, y + half); ++yy) {
        for (let xx = Math.max(0, x - half); xx <= Math.min(W - 1, x + half); ++xx) seen[yy * W + xx] = 1;
      }
    }
  }
  return seen;
}

function expectedColor(trace, map, i, seen) {
  const v = map[i];
  if (v < 0) return NON_HULL;
  if (v === 2) return seen[i] ? CORROSION : PRIOR_ONLY;
  if (v === 3) return INSPECTED;
  if (trace.partition) {
    const W = trace.grid.width;
    const ch = trace.partition[Math.floor(i / W)][i % W];
    const owner = ch >= 'A' ? ch.charCodeAt(0) - 55 : Number(ch);
    const region = REGIONS[owner % REGIONS.length];
    return v === 0 ? region : tint(region);
  }
  return v === 0 ? UNKNOWN : CLEAN;
}

const BROWSER_ARGS = [
  '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync',
];

let browser;
let mission; // {trace, html}
let synthetic; // {trace, html}
const measurements = {};

function cli(args) {
  return spawnSync(CLI, args, {encoding: 'utf8'});
}

before(async () => {
  assert.ok(CLI, 'set HULLINSPECT_CLI to the hullinspect binary (CTest does)');
  assert.ok(fs.existsSync(CLI), `HULLINSPECT_CLI=${CLI} does not exist: build it first`);
  fs.mkdirSync(OUT, {recursive: true});

  // A real mission: 8 UAVs, lawnmower (partitioned), with its trace and both ways to the page.
  const tracePath = path.join(OUT, 'mission.json');
  const runHtml = path.join(OUT, 'mission-run.html');
  const run = cli(['run', '--uavs', '8', '--seed', '3', '--trace', tracePath, '--html', runHtml]);
  assert.equal(run.status, 0, run.stderr);
  const viewHtml = path.join(OUT, 'mission.html');
  execFileSync(CLI, ['view', tracePath, '--out', viewHtml]);
  mission = {trace: JSON.parse(fs.readFileSync(tracePath, 'utf8')), html: viewHtml, runHtml};

  // A long synthetic mission: 8 UAVs × 5000 steps, annotations and a frontier layer every step.
  const started = Date.now();
  const long = syntheticTrace(mission.trace, {uavs: 8, steps: 5000, seed: 11});
  const longPath = path.join(OUT, 'synthetic-8x5000.json');
  fs.writeFileSync(longPath, JSON.stringify(long));
  const longHtml = path.join(OUT, 'synthetic-8x5000.html');
  execFileSync(CLI, ['view', longPath, '--out', longHtml]);
  synthetic = {trace: long, html: longHtml};
  measurements.synthetic_trace_mb = fs.statSync(longPath).size / 1e6;
  measurements.synthetic_generation_ms = Date.now() - started;

  browser = await Browser.launch(BROWSER_ARGS);
});

after(async () => {
  if (browser) await browser.close();
  fs.writeFileSync(path.join(OUT, 'measurements.json'), JSON.stringify(measurements, null, 2) + '\n');
});

const open = (file) => browser.open(file);

async function pixelOfCell(page, x, y) {
  return page.evaluate(({x, y}) => {
    const canvas = document.getElementById('grid-canvas');
    const {W, H} = window.hullViewer.replay;
    const sx = canvas.width / W;
    const sy = canvas.height / H;
    const data = canvas.getContext('2d').getImageData(Math.floor((x + 0.5) * sx),
                                                       Math.floor((H - 1 - y + 0.5) * sy), 1, 1).data;
    return [data[0], data[1], data[2]];
  }, {x, y});
}

// A few cells of every state present at time t (corrosion known only from the prior apart from
// detected corrosion), plus random ones.
const stateOf = (map, seen, i) => (map[i] === 2 && !seen[i] ? 'prior-only' : map[i]);
function sampleCells(trace, map, seen, seed) {
  const W = trace.grid.width;
  const byState = new Map();
  map.forEach((v, i) => {
    const s = stateOf(map, seen, i);
    if (!byState.has(s)) byState.set(s, []);
    byState.get(s).push(i);
  });
  const random = prng(seed);
  const cells = [];
  for (const list of byState.values()) {
    for (let j = 0; j < 3; ++j) cells.push(list[Math.floor(random() * list.length)]);
  }
  for (let j = 0; j < 10; ++j) cells.push(Math.floor(random() * map.length));
  return cells.map((i) => ({i, x: i % W, y: Math.floor(i / W)}));
}

async function checkCellsAt(page, trace, t) {
  await page.evaluate((t) => window.hullViewer.seek(t), t);
  await settle(page);
  assert.equal(await page.evaluate(() => window.hullViewer.time()), t);
  assert.match(await page.textContent('#time-display'), new RegExp(`^t = ${t} s`));
  const {map} = mapAt(trace, t);
  const seen = seenBy(trace, t);
  const states = new Set();
  for (const {i, x, y} of sampleCells(trace, map, seen, t + 1)) {
    states.add(stateOf(map, seen, i));
    assert.deepEqual(await pixelOfCell(page, x, y), expectedColor(trace, map, i, seen),
                     `cell (${x}, ${y}) at t = ${t}, M = ${map[i]}`);
  }
  return states;
}

test('run --html and view write the same self-contained page', () => {
  const a = fs.readFileSync(mission.html, 'utf8');
  assert.equal(fs.readFileSync(mission.runHtml, 'utf8'), a);
  assert.doesNotMatch(a, /<script[^>]*\ssrc=|<link[^>]*\shref=|https?:\/\//i);
});

test('the page loads nothing but itself', async () => {
  const {page, requests} = await open(mission.html);
  assert.deepEqual(requests, [`file://${mission.html}`]);
  await page.close();
});

test('shows the trace\'s T_c, T_m and counters', async () => {
  const {page} = await open(mission.html);
  const r = mission.trace.result;
  assert.equal(await page.textContent('#stat-tc'), `${r.T_c} s`);
  assert.equal(await page.textContent('#stat-tm'), `${r.T_m} s`);
  assert.match(await page.textContent('#stat-counters'), new RegExp(`moves ${r.moves} `));
  assert.equal(await page.$$eval('#uav-table tbody tr', (rows) => rows.length), 8);
  await page.click('#btn-tc');
  await settle(page);
  assert.equal(await page.evaluate(() => window.hullViewer.time()), r.T_c);
  await page.keyboard.press('m');
  await settle(page);
  assert.equal(await page.evaluate(() => window.hullViewer.time()), r.T_m);
  await page.close();
});

test('seeking draws the map of that time (forwards, backwards, across keyframes)', async () => {
  const {page} = await open(mission.html);
  const trace = mission.trace;
  const last = trace.frames.length - 1;
  const states = new Set();
  for (const t of [37, 120, last, 5, 0, Math.floor(last / 2)]) {
    for (const s of await checkCellsAt(page, trace, t)) states.add(s);
  }
  // Every cell state was among the checked pixels, corrosion known only from the prior (drawn
  // lighter) apart from detected corrosion.
  assert.deepEqual([...states].sort(), [-1, 0, 1, 2, 3, 'prior-only']);
  assert.ok(Math.hypot(...PRIOR_ONLY.map((v, i) => v - CORROSION[i])) > 80);
  await page.close();
});

test('the slider and the arrow keys move in time, play advances it', async () => {
  const {page} = await open(mission.html);
  await page.$eval('#slider', (s) => { s.value = '50'; s.dispatchEvent(new Event('input')); });
  await settle(page);
  assert.equal(await page.evaluate(() => window.hullViewer.time()), 50);
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowLeft');
  assert.equal(await page.evaluate(() => window.hullViewer.time()), 51);
  await page.keyboard.press('Shift+ArrowRight');
  assert.equal(await page.evaluate(() => window.hullViewer.time()), 61);
  await page.keyboard.press('Space');
  await page.waitForFunction(() => window.hullViewer.time() > 63, null, {timeout: 5000});
  await page.keyboard.press('Space');
  const paused = await page.evaluate(() => window.hullViewer.time());
  await page.waitForTimeout(300);
  assert.equal(await page.evaluate(() => window.hullViewer.time()), paused);
  assert.match(await page.textContent('#time-display'), new RegExp(`^t = ${paused} s`));
  // The play button does the same.
  await page.click('#btn-play');
  await page.waitForFunction((p) => window.hullViewer.time() > p, paused, {timeout: 5000});
  await page.click('#btn-play');
  assert.equal(await page.evaluate(() => window.hullViewer.viewer.playing), false);
  await page.close();
});

test('hovering a cell describes it', async () => {
  const {page} = await open(mission.html);
  await page.evaluate(() => window.hullViewer.seek(0));
  const box = await page.locator('#grid-canvas').boundingBox();
  const {width: W, height: H} = mission.trace.grid;
  const cell = box.width / W;
  await page.mouse.move(box.x + 100.5 * cell, box.y + (H - 1 - 20 + 0.5) * cell);
  await settle(page);
  const text = await page.textContent('#hover-info');
  const truth = mission.trace.truth[20][100];
  assert.match(text, new RegExp(`^cell \\(100, 20\\) .* truth C = ${truth} `));
  await page.close();
});

test('8 UAVs × 5000 steps open, seek and play smoothly', async (t) => {
  const {page, openMs} = await open(synthetic.html);
  const inPage = await page.evaluate(() => {
    const v = window.hullViewer;
    return {scriptAt: v.scriptAt, parseMs: v.parseMs, setupMs: v.setupMs, readyAt: v.readyAt};
  });
  measurements.synthetic_open_ms = Math.round(openMs);
  measurements.synthetic_ready_since_navigation_ms = Math.round(inPage.readyAt);
  measurements.synthetic_html_loaded_ms = Math.round(inPage.scriptAt);
  measurements.synthetic_json_parse_ms = Math.round(inPage.parseMs);
  measurements.synthetic_replay_setup_ms = Math.round(inPage.setupMs);
  t.diagnostic(`synthetic trace ${measurements.synthetic_trace_mb.toFixed(1)} MB: open ${openMs.toFixed(0)} ms; ` +
               `in the page: script starts at ${inPage.scriptAt.toFixed(0)} ms, JSON.parse ` +
               `${inPage.parseMs.toFixed(0)} ms, keyframes and first draw ${inPage.setupMs.toFixed(0)} ms, ` +
               `ready at ${inPage.readyAt.toFixed(0)} ms`);
  // Seeks, checked against the slow reconstruction.
  for (const time of [4999, 2500, 2499, 130, 4000]) await checkCellsAt(page, synthetic.trace, time);
  const seek = await page.evaluate(() => {
    const v = window.hullViewer;
    const started = performance.now();
    for (let i = 0; i < 200; ++i) v.replay.seek((i * 2654435761) % 5001);
    return (performance.now() - started) / 200;
  });
  measurements.synthetic_seek_ms = Number(seek.toFixed(3));
  // Drawing one frame (cells, overlays, chart, tables).
  const draw = await page.evaluate(() => {
    const v = window.hullViewer.viewer;
    const started = performance.now();
    for (let i = 0; i < 100; ++i) { v.replay.seek(1000 + i); v.draw(); }
    return (performance.now() - started) / 100;
  });
  measurements.synthetic_frame_ms = Number(draw.toFixed(2));
  t.diagnostic(`seek ${seek.toFixed(3)} ms, seek + draw one frame ${draw.toFixed(2)} ms`);
  await page.evaluate(() => window.hullViewer.seek(2000));
  await page.selectOption('#speed', '250');
  await page.keyboard.press('Space');
  await page.waitForTimeout(1000);
  await page.keyboard.press('Space');
  const reached = await page.evaluate(() => window.hullViewer.time());
  measurements.synthetic_play_steps_in_1s_at_250 = reached - 2000;
  assert.ok(reached > 2000, 'play advanced');
  await page.screenshot({path: path.join(OUT, 'viewer-synthetic.png'), fullPage: true});
  await page.close();
});

test('screenshot of a real mission', async (t) => {
  const {page, openMs} = await open(mission.html);
  measurements.mission_open_ms = Math.round(openMs);
  await page.evaluate(() => window.hullViewer.seek(90));
  await settle(page);
  const file = path.join(OUT, 'viewer-mission.png');
  await page.screenshot({path: file, fullPage: true});
  assert.ok(fs.statSync(file).size > 10000);
  t.diagnostic(`screenshots in ${OUT}`);
  await page.close();
});

// Layer cells at time t rebuilt independently from the trace: the last whole set at or before t,
// then the changes ({add, remove}) after it.
function layerAt(trace, name, t) {
  let set = new Set();
  for (let i = 0; i <= t; ++i) {
    const v = trace.frames[i].l && trace.frames[i].l[name];
    if (!v) continue;
    if (Array.isArray(v)) {
      set = new Set(v);
    } else {
      for (const c of v.remove || []) set.delete(c);
      for (const c of v.add || []) set.add(c);
    }
  }
  return [...set].sort((a, b) => a - b);
}

test('a 16-UAV Coop-Frontier trace of a 700 × 70 hull opens in a few seconds', async (t) => {
  const hull = path.join(OUT, 'rect-700x70.txt');
  fs.writeFileSync(hull, `${'X'.repeat(700)}\n`.repeat(70));
  const tracePath = path.join(OUT, 'coop-16-700x70.json');
  const html = path.join(OUT, 'coop-16-700x70.html');
  const run = cli(['run', '-a', 'coop-frontier', '--uavs', '16', '--hull', hull, '--seed', '1',
                   '--trace', tracePath, '--html', html]);
  assert.equal(run.status, 0, run.stderr);
  const trace = JSON.parse(fs.readFileSync(tracePath, 'utf8'));
  assert.equal(trace.version, 4);
  measurements.coop16_trace_mb = Number((fs.statSync(tracePath).size / 1e6).toFixed(2));
  measurements.coop16_steps = trace.frames.length - 1;
  const {page, openMs} = await open(html);
  measurements.coop16_open_ms = Math.round(openMs);
  t.diagnostic(`coop-frontier, 16 UAVs, 700 × 70: ${measurements.coop16_trace_mb} MB trace, ` +
               `${measurements.coop16_steps} steps, open ${openMs.toFixed(0)} ms`);
  assert.ok(openMs < 10000, `opening took ${openMs.toFixed(0)} ms`);
  // The frontier layer the page shows is the one the trace describes, forwards and backwards.
  const last = trace.frames.length - 1;
  for (const time of [0, 1, 129, 300, last, 200, 201, 5]) {
    const shown = await page.evaluate((time) => {
      const r = window.hullViewer.replay;
      return [...r.layer('frontiers', time)].sort((a, b) => a - b);
    }, time);
    assert.deepEqual(shown, layerAt(trace, 'frontiers', time), `frontiers at t = ${time}`);
  }
  const seekDraw = await page.evaluate((last) => {
    const v = window.hullViewer.viewer;
    const started = performance.now();
    for (let i = 0; i < 50; ++i) { v.replay.seek((i * 7919) % (last + 1)); v.draw(); }
    return (performance.now() - started) / 50;
  }, last);
  measurements.coop16_seek_draw_ms = Number(seekDraw.toFixed(2));
  await page.close();
});

// Screenshots of the map checked against committed references (viewer/test/reference/): at most
// 1 % of the pixels may differ by more than 24 in a channel (anti-aliasing, font hinting).
// HULLINSPECT_UPDATE_REFERENCES=1 writes the references instead (then look at them).
const REFERENCE_DIR = path.join(path.dirname(new URL(import.meta.url).pathname), 'reference');

async function compareWithReference(page, name) {
  const file = path.join(OUT, `${name}.png`);
  await page.locator('#map-panel').screenshot({path: file});
  const reference = path.join(REFERENCE_DIR, `${name}.png`);
  if (process.env.HULLINSPECT_UPDATE_REFERENCES) {
    fs.mkdirSync(REFERENCE_DIR, {recursive: true});
    fs.copyFileSync(file, reference);
    return;
  }
  assert.ok(fs.existsSync(reference), `${reference} is missing (HULLINSPECT_UPDATE_REFERENCES=1)`);
  const url = (f) => `data:image/png;base64,${fs.readFileSync(f).toString('base64')}`;
  const result = await page.evaluate(async ({a, b}) => {
    const load = (src) => new Promise((resolve, reject) => {
      const image = new Image();
      image.onload = () => resolve(image);
      image.onerror = () => reject(new Error('cannot decode'));
      image.src = src;
    });
    const [ia, ib] = await Promise.all([load(a), load(b)]);
    if (ia.width !== ib.width || ia.height !== ib.height) {
      return {size: `${ia.width}×${ia.height} against the reference's ${ib.width}×${ib.height}`};
    }
    const pixels = (image) => {
      const c = document.createElement('canvas');
      c.width = image.width;
      c.height = image.height;
      const ctx = c.getContext('2d');
      ctx.drawImage(image, 0, 0);
      return ctx.getImageData(0, 0, c.width, c.height).data;
    };
    const pa = pixels(ia);
    const pb = pixels(ib);
    let differing = 0;
    for (let i = 0; i < pa.length; i += 4) {
      if (Math.abs(pa[i] - pb[i]) > 24 || Math.abs(pa[i + 1] - pb[i + 1]) > 24 ||
          Math.abs(pa[i + 2] - pb[i + 2]) > 24) ++differing;
    }
    return {differing, total: pa.length / 4};
  }, {a: url(file), b: url(reference)});
  assert.equal(result.size, undefined, `${name}: ${result.size}`);
  const share = result.differing / result.total;
  measurements[`${name}_differing_pixel_share`] = Number(share.toFixed(5));
  assert.ok(share <= 0.01, `${name}: ${(100 * share).toFixed(2)} % of the pixels differ from ${reference}`);
}

async function missionPage(name, args, time, setup) {
  const html = path.join(OUT, `${name}.html`);
  const run = cli(['run', ...args, '--html', html]);
  assert.equal(run.status, 0, run.stderr);
  const {page} = await open(html);
  await page.setViewportSize({width: 1400, height: 900});
  if (setup) await setup(page);
  await page.evaluate((t) => window.hullViewer.seek(t), time);
  await settle(page);
  return page;
}

test('screenshots of 4 and 8 UAVs match the references', async () => {
  // 4 UAVs, Coop-Frontier (frontier layer, labels close together), imperfect prior.
  const four = await missionPage('viewer-4-coop-frontier',
                                 ['-a', 'coop-frontier', '--uavs', '4', '--seed', '3', '--scenario',
                                  'imperfect'], 60);
  await compareWithReference(four, 'viewer-4-coop-frontier');
  await four.close();
  // 8 UAVs, Part-TSP with regions, the truth shown and a hovered cell near the top row.
  const eight = await missionPage('viewer-8-part-tsp',
                                  ['-a', 'part-tsp', '--uavs', '8', '--seed', '3', '--scenario',
                                   'imperfect'], 90, async (page) => {
                                    await page.check('#show-truth');
                                  });
  const box = await eight.locator('#grid-canvas').boundingBox();
  const cell = box.width / 230;
  await eight.mouse.move(box.x + 120.5 * cell, box.y + 1.5 * cell);
  await settle(eight);
  await compareWithReference(eight, 'viewer-8-part-tsp');
  await eight.close();
});

// Label geometry at every checked time of a mission: the map's label ink boxes (map_view.js keeps
// them, stroke halo included) against each other, against every UAV marker (placed here from the
// trace's positions) and against the part of the page where the map is visible.
async function labelProblems(page, trace, times) {
  return page.evaluate(({frames, times}) => {
    const v = window.hullViewer.viewer;
    const r = v.replay;
    const grid = document.getElementById('grid-canvas').getBoundingClientRect();
    const overlay = document.getElementById('overlay-canvas').getBoundingClientRect();
    const scroll = document.getElementById('map-scroll').getBoundingClientRect();
    const cell = grid.width / r.W;
    // A marker's ink: its disc, the ring around a UAV at z = 1 (radius + 1.25, 1 px wide).
    const rad = v.map.markerRadius() + 1.75;
    const problems = [];
    let labels = 0;
    let leaders = 0;
    const intersect = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
    for (const t of times) {
      v.replay.seek(t);
      v.draw();
      // Page coordinates.
      const boxes = v.map.labelBoxes.map((b) => ({...b, x: b.x + overlay.left, y: b.y + overlay.top}));
      const u = frames[t].u;
      const markers = [];
      for (let o = 0; o < u.length; o += 5) {
        markers.push({x: grid.left + (u[o] + 0.5) * cell - rad, y: grid.top + (r.H - 1 - u[o + 1] + 0.5) * cell - rad,
                      w: 2 * rad, h: 2 * rad});
      }
      if (boxes.length !== markers.length) problems.push(`t = ${t}: ${boxes.length} labels for ${markers.length} UAVs`);
      labels += boxes.length;
      boxes.forEach((b, i) => {
        if (b.leader) ++leaders;
        if (!b.text.startsWith(`${b.k}`)) problems.push(`t = ${t}: label '${b.text}' of UAV ${b.k}`);
        const where = `t = ${t}: label '${b.text}' [${b.x.toFixed(1)}, ${b.y.toFixed(1)}, ${b.w.toFixed(1)} × ${b.h.toFixed(1)}]`;
        for (const [name, area] of [['the overlay canvas', overlay], ['the visible map', scroll]]) {
          if (b.x < area.left - 1e-6 || b.y < area.top - 1e-6 || b.x + b.w > area.right + 1e-6 ||
              b.y + b.h > area.bottom + 1e-6) problems.push(`${where} is clipped by ${name}`);
        }
        for (let j = 0; j < i; ++j) {
          if (intersect(b, boxes[j])) problems.push(`${where} overlaps label '${boxes[j].text}'`);
        }
        markers.forEach((m, k) => { if (intersect(b, m)) problems.push(`${where} covers UAV ${k}`); });
      });
    }
    return {problems, labels, leaders};
  }, {frames: trace.frames, times});
}

test('mode labels of 4, 8 and 16 UAVs neither overlap nor are clipped, top row included', async (t) => {
  for (const [uavs, algorithm] of [[4, 'coop-frontier'], [8, 'part-tsp'], [16, 'coop-frontier'], [16, 'lawnmower']]) {
    const name = `labels-${uavs}-${algorithm}`;
    const tracePath = path.join(OUT, `${name}.json`);
    const html = path.join(OUT, `${name}.html`);
    const run = cli(['run', '-a', algorithm, '--uavs', String(uavs), '--seed', '5', '--trace', tracePath,
                     '--html', html]);
    assert.equal(run.status, 0, run.stderr);
    const trace = JSON.parse(fs.readFileSync(tracePath, 'utf8'));
    const {page} = await open(html);
    await page.setViewportSize({width: 1400, height: 900});
    await settle(page);
    const last = trace.frames.length - 1;
    const stride = Math.max(1, Math.floor(last / 300));
    const times = [];
    for (let time = 0; time <= last; time += stride) times.push(time);
    // The top row is where labels were clipped: every time a UAV is on it is checked.
    const top = trace.grid.height - 1;
    trace.frames.forEach((f, time) => {
      for (let o = 1; o < f.u.length; o += 5) if (f.u[o] === top && time % stride) times.push(time);
    });
    const {problems, labels, leaders} = await labelProblems(page, trace, times);
    t.diagnostic(`${name}: ${times.length} times, ${labels} labels, ${leaders} placed away from their UAV`);
    measurements[`${name}_labels_with_leader_share`] = Number((leaders / labels).toFixed(4));
    assert.deepEqual(problems.slice(0, 10), [], `${problems.length} problems`);
    await page.close();
  }
});

// The obstacles preset's no-fly zones (presets/obstacles.yaml: four mooring lines and a gangway,
// there in metres) as cell boxes, corners inclusive.
const OBSTACLE_BOXES = [[20, 10, 20, 29], [40, 10, 40, 29], [190, 10, 190, 29], [210, 10, 210, 29],
  [110, 18, 117, 29]];
const NO_FLY_MARK = [17, 17, 17];
const UNREACHABLE_MARK = [null, [153, 153, 153], [68, 68, 68]]; // 'd' only z = 2 sees it, 'x' none

async function obstaclesMission() {
  const tracePath = path.join(OUT, 'obstacles.json');
  const html = path.join(OUT, 'obstacles.html');
  const run = cli(['run', '-a', 'part-tsp', '--uavs', '8', '--seed', '3', '--scenario', 'imperfect',
                   ...OBSTACLE_BOXES.flatMap((b) => ['--no-fly-box', b.join(',')]), '--trace', tracePath,
                   '--html', html]);
  assert.equal(run.status, 0, run.stderr);
  return {trace: JSON.parse(fs.readFileSync(tracePath, 'utf8')), html};
}

test('no-fly zones are hatched exactly at their positions, unreachable cells marked, both in the legend', async () => {
  const {trace, html} = await obstaclesMission();
  const {width: W, height: H} = trace.grid;
  // The trace's no-fly layer is the boxes given.
  const noFly = new Uint8Array(W * H);
  for (const [x0, y0, x1, y1] of OBSTACLE_BOXES) {
    for (let y = y0; y <= y1; ++y) for (let x = x0; x <= x1; ++x) noFly[y * W + x] = 1;
  }
  const unreachable = new Uint8Array(W * H);
  for (let y = 0; y < H; ++y) {
    for (let x = 0; x < W; ++x) {
      assert.equal(trace.no_fly[y][x] === '#', noFly[y * W + x] === 1, `no_fly at (${x}, ${y})`);
      unreachable[y * W + x] = {d: 1, x: 2}[trace.unreachable[y][x]] || 0;
    }
  }
  const kinds = [0, 0, 0];
  unreachable.forEach((u) => ++kinds[u]);
  assert.ok(kinds[1] > 0 && kinds[2] > 0, `unreachable cells of both kinds: ${kinds}`);
  assert.equal(kinds[1] + kinds[2], trace.result.unreachable_cells);

  const {page} = await open(html);
  await page.setViewportSize({width: 1400, height: 900});
  // Everything but the cells, the hatching and the UAVs off; 16 px cells so one hatch line
  // crosses known pixels: '/' (no-fly) the pixel (4, 11) of a cell, '\' (unreachable) (4, 4).
  await page.evaluate(() => {
    for (const name of ['footprints', 'paths', 'plans', 'targets', 'layers', 'labels']) {
      const box = document.getElementById(`show-${name}`);
      box.checked = false;
      box.dispatchEvent(new Event('change'));
    }
  });
  await page.selectOption('#zoom', '16');
  await page.evaluate(() => window.hullViewer.seek(100));
  await settle(page);
  const wrong = await page.evaluate(({noFly, unreachable, NO_FLY_MARK, UNREACHABLE_MARK}) => {
    const v = window.hullViewer.viewer;
    const r = v.replay;
    const cp = v.map.cellPx;
    const pad = window.hullinspectViewer.MapView.padding;
    const canvas = document.getElementById('overlay-canvas');
    const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    const at = (px, py) => {
      const o = (py * canvas.width + px) * 4;
      return [data[o], data[o + 1], data[o + 2], data[o + 3]];
    };
    const near = (p, c) => p[3] > 160 && c.every((v, i) => Math.abs(p[i] - v) <= 40);
    const rad = v.map.markerRadius() + 3;
    const uavs = [];
    for (let k = 0; k < r.uavCount; ++k) uavs.push(r.uavState(r.t, k));
    const out = [];
    let checked = 0;
    for (let y = 0; y < r.H; ++y) {
      for (let x = 0; x < r.W; ++x) {
        const ox = Math.round(pad.left + x * cp);
        const oy = Math.round(pad.top + (r.H - 1 - y) * cp);
        // Pixels a UAV marker may cover are not checked.
        if (uavs.some((s) => Math.hypot((s.x - x) * cp, (s.y - y) * cp) < rad + cp)) continue;
        ++checked;
        const i = y * r.W + x;
        const slash = at(ox + 4, oy + 11);
        const backslash = at(ox + 4, oy + 4);
        if (noFly[i] ? !near(slash, NO_FLY_MARK) : slash[3] !== 0) out.push(`(${x}, ${y}) '/' ${slash}`);
        const u = unreachable[i];
        const want = u ? (noFly[i] ? NO_FLY_MARK : UNREACHABLE_MARK[u]) : null;
        if (want ? !near(backslash, want) : backslash[3] !== 0) out.push(`(${x}, ${y}) '\\' ${backslash}`);
      }
    }
    return {out, checked};
  }, {noFly: [...noFly], unreachable: [...unreachable], NO_FLY_MARK, UNREACHABLE_MARK});
  assert.ok(wrong.checked > 0.95 * W * H, `${wrong.checked} cells checked`);
  assert.deepEqual(wrong.out.slice(0, 10), [], `${wrong.out.length} cells hatched wrongly`);

  const legend = await page.$$eval('#legend li', (items) => items.map((li) => li.textContent));
  for (const text of ['no-fly position (no UAV may be there)', 'unreachable for close-up: only z = 2 sees it',
    'unreachable: no footprint sees it']) {
    assert.ok(legend.includes(text), `legend lacks '${text}': ${legend.join(' | ')}`);
  }
  assert.match(await page.textContent('#stat-mission'),
               new RegExp(`, ${trace.result.unreachable_cells} unreachable for close-up`));
  // The hover line names them.
  const box = await page.locator('#grid-canvas').boundingBox();
  const hover = async (x, y) => {
    await page.mouse.move(box.x + (x + 0.5) * 16, box.y + (H - 1 - y + 0.5) * 16);
    await settle(page);
    return page.textContent('#hover-info');
  };
  await page.evaluate(() => document.getElementById('map-scroll').scrollTo(0, 0));
  assert.match(await hover(20, 15), /no-fly position/);
  const d = unreachable.indexOf(1);
  await page.evaluate((x) => document.getElementById('map-scroll').scrollTo(Math.max(0, x * 16 - 400), 0), d % W);
  const scrolled = await page.evaluate(() => document.getElementById('map-scroll').scrollLeft);
  await page.mouse.move(box.x - scrolled + (d % W + 0.5) * 16, box.y + (H - 1 - Math.floor(d / W) + 0.5) * 16);
  await settle(page);
  assert.match(await page.textContent('#hover-info'), /unreachable for close-up \(only z = 2 sees it\)/);
  await page.close();

  // Without no-fly zones there is no hatching entry.
  const plain = await open(mission.html);
  const plainLegend = await plain.page.$$eval('#legend li', (items) => items.map((li) => li.textContent).join(' | '));
  assert.doesNotMatch(plainLegend, /no-fly|unreachable/);
  await plain.page.close();
});

test('screenshot with no-fly zones matches the reference', async () => {
  const args = ['-a', 'part-tsp', '--uavs', '8', '--seed', '3', '--scenario', 'imperfect',
                ...OBSTACLE_BOXES.flatMap((b) => ['--no-fly-box', b.join(',')])];
  const page = await missionPage('viewer-8-obstacles', args, 100);
  await compareWithReference(page, 'viewer-8-obstacles');
  await page.close();
});

test('region colours and tints are neither the footprint blue nor the unknown grey', async () => {
  const {page} = await open(mission.html);
  const fill = await page.evaluate(() => window.hullinspectViewer.palette.FOOTPRINT_FILL);
  await page.close();
  const [fr, fg, fb, fa] = fill.match(/[\d.]+/g).map(Number);
  const overUnknown = UNKNOWN.map((v, i) => Math.round(v * (1 - fa) + [fr, fg, fb][i] * fa));
  const hue = ([r, g, b]) => {
    const max = Math.max(r, g, b);
    const c = max - Math.min(r, g, b);
    const h = max === r ? ((g - b) / c) % 6 : max === g ? (b - r) / c + 2 : (r - g) / c + 4;
    return (h * 60 + 360) % 360;
  };
  const distance = (a, b) => Math.hypot(...a.map((v, i) => v - b[i]));
  const footprintHue = hue([fr, fg, fb]);
  // Neighbouring regions (k and k + 1 usually share a boundary) differ clearly; with 8 UAVs no two
  // regions are alike.
  REGIONS.forEach((c, k) => {
    for (const shown of [c, tint(c)]) {
      assert.ok(distance(shown, UNKNOWN) >= 50, `region ${k} ${shown} near the unknown grey`);
      assert.ok(distance(shown, overUnknown) >= 50, `region ${k} ${shown} near a footprint over unknown`);
      assert.ok(Math.abs(hue(shown) - footprintHue) >= 30, `region ${k} ${shown}: hue ${hue(shown)} is the footprint's`);
    }
    assert.ok(Math.max(...c) - Math.min(...c) >= 60, `region ${k} ${c} is greyish`);
    if (k > 0) assert.ok(distance(c, REGIONS[k - 1]) >= 60, `regions ${k - 1} and ${k} alike`);
    if (k < 8) {
      for (let j = 0; j < k; ++j) assert.ok(distance(c, REGIONS[j]) >= 35, `regions ${j} and ${k} alike`);
    }
  });
});

test('the axes are in metres along the hull, stern on the left and bow on the right', async () => {
  const {page} = await open(mission.html);
  const {texts, cellPx} = await page.evaluate(() => ({texts: window.hullViewer.viewer.map.axisTexts,
    cellPx: window.hullViewer.viewer.map.cellPx}));
  await page.close();
  const {width: W, height: H, cell_size_m: m} = mission.trace.grid;
  assert.ok(m > 0);
  const one = (kind) => {
    const found = texts.filter((t) => t.kind === kind);
    assert.equal(found.length, 1, kind);
    return found[0];
  };
  assert.equal(one('x-title').text, 'x (m, along the hull)');
  assert.equal(one('y-title').text, 'y (m)');
  assert.equal(one('stern').text, '◀ stern');
  assert.equal(one('bow').text, 'bow ▶');
  assert.ok(one('stern').x < one('x-title').x && one('x-title').x < one('bow').x);
  // Ticks: at their value in metres, from 0 to the hull's length (height), evenly spaced.
  for (const [kind, extent, position] of [['x-tick', W, (v) => 46 + (v / m) * cellPx],
    ['y-tick', H, (v) => 18 + (H - v / m) * cellPx]]) {
    const ticks = texts.filter((t) => t.kind === kind);
    assert.ok(ticks.length >= 3, kind);
    const values = ticks.map((t) => Number(t.text));
    assert.equal(values[0], 0);
    const step = values[1] - values[0];
    values.forEach((v, i) => assert.ok(Math.abs(v - i * step) < 1e-9, `${kind} ${values}`));
    assert.ok(values.at(-1) <= extent * m + 1e-9 && values.at(-1) + step > extent * m, `${kind} ${values}`);
    ticks.forEach((t, i) => {
      const at = kind === 'x-tick' ? t.x : t.y;
      assert.ok(Math.abs(at - position(values[i])) < 0.01, `${kind} ${t.text} at ${at}`);
    });
  }
});

// Overlay pixel (RGBA) at CSS px (x, y) of the overlay canvas.
async function overlayPixels(page, points) {
  return page.evaluate((points) => {
    const c = document.getElementById('overlay-canvas');
    const dpr = c.width / c.getBoundingClientRect().width;
    const ctx = c.getContext('2d');
    return points.map(([x, y]) => Array.from(ctx.getImageData(Math.floor(x * dpr), Math.floor(y * dpr), 1, 1).data));
  }, points);
}

async function onlyCellsAndUavs(page) {
  await page.evaluate(() => {
    for (const name of ['footprints', 'paths', 'plans', 'targets', 'layers', 'labels']) {
      const box = document.getElementById(`show-${name}`);
      box.checked = false;
      box.dispatchEvent(new Event('change'));
    }
  });
}

test('"show truth" marks exactly the corroded cells not detected yet, and only when on', async () => {
  // An imperfect prior: corroded cells the prior misses stay unknown (M = 0) until detected.
  const tracePath = path.join(OUT, 'truth.json');
  const html = path.join(OUT, 'truth.html');
  const run = cli(['run', '--uavs', '8', '--seed', '3', '--scenario', 'imperfect', '--trace', tracePath,
                   '--html', html]);
  assert.equal(run.status, 0, run.stderr);
  const trace = JSON.parse(fs.readFileSync(tracePath, 'utf8'));
  const {page} = await open(html);
  await onlyCellsAndUavs(page);
  const {width: W, height: H} = trace.grid;
  const t = 40;
  await page.evaluate((t) => window.hullViewer.seek(t), t);
  await settle(page);
  const {map} = mapAt(trace, t);
  const {cellPx: cp, rad} = await page.evaluate(() => ({cellPx: window.hullViewer.viewer.map.cellPx,
    rad: window.hullViewer.viewer.map.markerRadius()}));
  const uavs = [];
  for (let o = 0; o < trace.frames[t].u.length; o += 5) uavs.push(trace.frames[t].u.slice(o, o + 2));
  const cells = [];
  const kinds = {undetected: 0, detected: 0, clean: 0};
  for (let y = 0; y < H; ++y) {
    for (let x = 0; x < W; ++x) {
      const i = y * W + x;
      if (map[i] < 0 || uavs.some(([ux, uy]) => Math.hypot(ux - x, uy - y) * cp < rad + 2 * cp)) continue;
      const truth = Number(trace.truth[y][x]);
      const kind = truth === 1 ? (map[i] === 0 ? 'undetected' : 'detected') : 'clean';
      if (kinds[kind] >= 60) continue;
      ++kinds[kind];
      cells.push({kind, x, y, at: [46 + (x + 0.5) * cp, 18 + (H - 1 - y + 0.5) * cp]});
    }
  }
  assert.ok(kinds.undetected > 10 && kinds.detected > 10, JSON.stringify(kinds));
  const off = await overlayPixels(page, cells.map((c) => c.at));
  off.forEach((p, j) => assert.equal(p[3], 0, `truth off: (${cells[j].x}, ${cells[j].y}) ${p}`));
  await page.check('#show-truth');
  await settle(page);
  const on = await overlayPixels(page, cells.map((c) => c.at));
  on.forEach((p, j) => {
    const want = cells[j].kind === 'undetected' ? [200, 0, 0, 255] : [0, 0, 0, 0];
    assert.deepEqual(p, want, `truth on: ${cells[j].kind} (${cells[j].x}, ${cells[j].y})`);
  });
  const legend = await page.$$eval('#legend li', (items) => items.map((li) => li.textContent));
  assert.ok(legend.includes('corrosion not detected yet (truth; planners do not see it)'));
  await page.close();
});

test('the hovered cell is marked in yellow, unlike targets (white with a UAV colour)', async () => {
  const html = path.join(OUT, 'viewer-8-part-tsp.html');
  if (!fs.existsSync(html)) {
    assert.equal(cli(['run', '-a', 'part-tsp', '--uavs', '8', '--seed', '3', '--scenario', 'imperfect',
                      '--html', html]).status, 0);
  }
  const {page} = await open(html);
  await page.selectOption('#zoom', '16');
  await page.evaluate(() => window.hullViewer.seek(90));
  await settle(page);
  const info = await page.evaluate(() => {
    const v = window.hullViewer.viewer;
    const r = v.replay;
    const targets = [];
    for (let k = 0; k < r.uavCount; ++k) {
      const a = r.annotation(k, r.t);
      if (a && a.target) targets.push({k, x: a.target[0], y: a.target[1], colour: window.hullinspectViewer.palette.uavColor(k)});
    }
    return {targets, H: r.H, hover: window.hullinspectViewer.palette.HOVER_MARK};
  });
  assert.ok(info.targets.length > 0, 'a UAV with a target at t = 90');
  const cp = 16;
  const {H} = info;
  const topLeft = (x, y) => [46 + x * cp, 18 + (H - 1 - y) * cp];
  const target = info.targets[0];
  const [tx, ty] = topLeft(target.x, target.y);
  const uavRgb = target.colour.match(/\d+/g).map(Number);
  // The target: white inside, the UAV's colour on its border (2 px line around the padded cell).
  const [inside, border] = await overlayPixels(page, [[tx + cp / 2, ty + cp / 2], [tx - 2.4 - 0.5, ty + cp / 2]]);
  assert.deepEqual(inside, [255, 255, 255, 255]);
  assert.deepEqual(border.slice(0, 3), uavRgb);
  // Hover a cell away from the targets: a yellow ring 2.5 px outside the cell.
  const hx = (target.x + 20) % 200;
  const hy = 10;
  const box = await page.locator('#grid-canvas').boundingBox();
  await page.evaluate((x) => document.getElementById('map-scroll').scrollTo(Math.max(0, x * 16 - 400), 0), hx);
  const scrolled = await page.evaluate(() => document.getElementById('map-scroll').scrollLeft);
  await page.mouse.move(box.x - scrolled + (hx + 0.5) * cp, box.y + (H - 1 - hy + 0.5) * cp);
  await settle(page);
  assert.match(await page.textContent('#hover-info'), new RegExp(`^cell \\(${hx}, ${hy}\\)`));
  const [hxPx, hyPx] = topLeft(hx, hy);
  const [ring] = await overlayPixels(page, [[hxPx - 2.5, hyPx + cp / 2]]);
  const yellow = [255, 212, 0];
  assert.equal(info.hover, '#ffd400');
  assert.ok(ring.slice(0, 3).every((v, i) => Math.abs(v - yellow[i]) <= 10), `hover ring ${ring}`);
  const distance = (a, b) => Math.hypot(...a.map((v, i) => v - b[i]));
  assert.ok(distance(yellow, [255, 255, 255]) > 150);
  for (let k = 0; k < 8; ++k) {
    const c = await page.evaluate((k) => window.hullinspectViewer.palette.uavColor(k), k);
    assert.ok(distance(yellow, c.match(/\d+/g).map(Number)) > 150, `UAV ${k} colour ${c} near the hover yellow`);
  }
  await page.close();
});

test('16 UAVs packed in the top-left corner: every label placed, none overlapping or clipped', async (t) => {
  // The 16-UAV lawnmower trace of the test above with its UAVs held in place (the trace reader
  // checks the model's motion rules, so every frame holds them): a 4 × 4 block of UAVs two cells
  // apart in the corner of the top row, where labels have least room.
  const trace = JSON.parse(fs.readFileSync(path.join(OUT, 'labels-16-lawnmower.json'), 'utf8'));
  const H = trace.grid.height;
  for (const frame of trace.frames) {
    for (let k = 0; k < 16; ++k) {
      frame.u[5 * k] = 2 * (k % 4);
      frame.u[5 * k + 1] = H - 1 - 2 * Math.floor(k / 4);
    }
  }
  const tracePath = path.join(OUT, 'labels-packed.json');
  const html = path.join(OUT, 'labels-packed.html');
  fs.writeFileSync(tracePath, JSON.stringify(trace));
  execFileSync(CLI, ['view', tracePath, '--out', html]);
  const {page} = await open(html);
  await page.setViewportSize({width: 1400, height: 900});
  await settle(page);
  const {problems, labels, leaders} = await labelProblems(page, trace, [0]);
  t.diagnostic(`packed: ${labels} labels, ${leaders} placed away from their UAV`);
  assert.deepEqual(problems.slice(0, 10), [], `${problems.length} problems`);
  assert.ok(leaders > 0, 'the crowding needs labels further out');
  await page.close();
});
