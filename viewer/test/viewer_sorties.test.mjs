// Browser test of the replay viewer on a mission with launch sites and batteries: a UAV on the
// ground or flying between its site and the hull is drawn as such (not as a UAV at work on the
// hull, no footprint), and every UAV has a battery gauge, red at or below the reserve.
// Run by CTest as `viewer_browser_sorties` (HULLINSPECT_CLI = the built CLI), or by hand:
//   HULLINSPECT_CLI=build/release/hullinspect node --test viewer/test/viewer_sorties.test.mjs

import {after, before, test} from 'node:test';
import assert from 'node:assert/strict';
import {spawnSync} from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

import {Browser, settle} from './browser.mjs';

const CLI = process.env.HULLINSPECT_CLI;
const OUT = process.env.HULLINSPECT_TEST_OUTPUT ||
    fs.mkdtempSync(path.join(os.tmpdir(), 'hullinspect-viewer-sorties-test-'));

// The viewer's colours (viewer/palette.js), written out again on purpose.
const GROUND_FILL = [60, 60, 60];
const AWAY_FILL = [138, 138, 138];
const BATTERY_OK = 'rgb(60, 170, 90)';
const BATTERY_LOW = 'rgb(215, 40, 40)';
const FIELDS = 8; // x, y, z, transit_left, active, airborne, battery_left, away_left

let browser;
let trace;
let html;

function cli(args) {
  const run = spawnSync(CLI, args, {encoding: 'utf8'});
  assert.equal(run.status, 0, run.stderr);
}

const uav = (t, k) => {
  const u = trace.frames[t].u.slice(FIELDS * k, FIELDS * (k + 1));
  return {x: u[0], y: u[1], airborne: u[5] === 1, battery: u[6], away: u[7]};
};
// The first time after `from` at which UAV k is as `want` says.
function firstTime(k, from, want) {
  for (let t = from; t < trace.frames.length; ++t) if (want(uav(t, k))) return t;
  assert.fail(`UAV ${k} never is as wanted after t = ${from}`);
}

before(async () => {
  assert.ok(CLI, 'set HULLINSPECT_CLI to the hullinspect binary (CTest does)');
  fs.mkdirSync(OUT, {recursive: true});
  // Two UAVs, a launch site each on the bottom edge, batteries of 600 s swapped in 30 s.
  const tracePath = path.join(OUT, 'sorties.json');
  html = path.join(OUT, 'sorties.html');
  cli(['run', '--uavs', '2', '--seed', '2', '--launch', '57,0', '--launch', '172,0', '--endurance', '600',
       '--swap-time', '30', '--trace', tracePath, '--html', html]);
  trace = JSON.parse(fs.readFileSync(tracePath, 'utf8'));
  browser = await Browser.launch(['--no-sandbox', '--disable-gpu', '--no-first-run']);
});

after(async () => {
  if (browser) await browser.close();
});

async function openAt(file, t) {
  const {page} = await browser.open(file);
  await page.setViewportSize({width: 1400, height: 900});
  // Only the cells and the UAVs: footprints checked apart, labels and paths off.
  await page.evaluate(() => {
    for (const name of ['paths', 'plans', 'targets', 'layers', 'labels']) {
      const box = document.getElementById(`show-${name}`);
      box.checked = false;
      box.dispatchEvent(new Event('change'));
    }
  });
  await page.selectOption('#zoom', '16');
  await seek(page, t);
  return page;
}

async function seek(page, t) {
  await page.evaluate((t) => window.hullViewer.seek(t), t);
  await settle(page);
}

// The overlay's pixel at the centre of cell (x, y).
function overlayPixel(page, x, y) {
  return page.evaluate(({x, y}) => {
    const v = window.hullViewer.viewer;
    const pad = window.hullinspectViewer.MapView.padding;
    const canvas = document.getElementById('overlay-canvas');
    const px = Math.round(pad.left + v.map.cx(x));
    const py = Math.round(pad.top + v.map.cy(y));
    const d = canvas.getContext('2d').getImageData(px, py, 1, 1).data;
    return [d[0], d[1], d[2], d[3]];
  }, {x, y});
}

// The UAV table's flight state and battery of UAV k: text, gauge length and colour.
function uavRow(page, k) {
  return page.evaluate((k) => {
    const row = document.querySelectorAll('#uav-table tbody tr')[k];
    const fill = row.querySelector('.gauge-fill');
    return {flight: row.querySelector('.flight').textContent, battery: row.querySelector('.gauge-text').textContent,
      width: fill.style.width, color: fill.style.background};
  }, k);
}

test('the trace records a swap: UAV 0 lands mid-mission, waits, and takes off again', () => {
  const takeoff = firstTime(0, 0, (s) => s.airborne);
  const landing = firstTime(0, takeoff, (s) => !s.airborne);
  assert.ok(landing < trace.result.T_m - 50, `UAV 0 first lands at ${landing}, T_m = ${trace.result.T_m}`);
  assert.deepEqual(trace.launch.sites, [[57, 0], [172, 0]]);
  assert.equal(trace.battery.endurance_steps, 600);
});

test('a UAV on the ground is a dark triangle at its site, one flying to or from it a grey diamond', async () => {
  const takeoff = firstTime(0, 0, (s) => s.airborne);
  const landing = firstTime(0, takeoff, (s) => !s.airborne);
  const ground = landing + 5; // swapping its battery
  const away = firstTime(0, ground, (s) => s.airborne && s.away > 0 && (s.y > 2 || s.x !== 57));
  const page = await openAt(html, ground);
  const s = uav(ground, 0);
  assert.deepEqual([s.x, s.y], [57, 0]);
  assert.deepEqual((await overlayPixel(page, s.x, s.y)).slice(0, 3), GROUND_FILL);
  assert.deepEqual(await page.$$eval('#uav-table thead th', (th) => th.map((h) => h.textContent)),
                   ['UAV', 'cell', 'plane', 'mode', 'target', 'flight', 'battery']);
  assert.equal((await uavRow(page, 0)).flight, 'on the ground');
  // UAV 1 at work on the hull meanwhile (or itself away): the table says which.
  const other = uav(ground, 1);
  assert.equal((await uavRow(page, 1)).flight, !other.airborne ? 'on the ground' : other.away ? 'away' : 'airborne');

  await seek(page, away);
  const a = uav(away, 0);
  assert.deepEqual((await overlayPixel(page, a.x, a.y)).slice(0, 3), AWAY_FILL);
  assert.equal((await uavRow(page, 0)).flight, 'away');
  // No footprint around a UAV away: the cell beside it shows no footprint blue on the overlay.
  const beside = await overlayPixel(page, a.x === 0 ? 1 : a.x - 1, a.y);
  assert.ok(beside[3] === 0 || !(beside[2] > beside[0] + 40), `footprint drawn beside UAV 0: ${beside}`);

  // At work on the hull: the round marker, never the triangle or the diamond.
  const work = firstTime(0, takeoff, (s) => s.airborne && s.away === 0);
  await seek(page, work);
  const w = uav(work, 0);
  const centre = (await overlayPixel(page, w.x, w.y)).slice(0, 3);
  assert.notDeepEqual(centre, GROUND_FILL);
  assert.notDeepEqual(centre, AWAY_FILL);
  assert.equal((await uavRow(page, 0)).flight, 'airborne');
  await page.screenshot({path: path.join(OUT, 'sorties-away.png')});
  await page.close();
});

test('the battery gauge shows the seconds left, green above the reserve and red at it', async () => {
  const t = firstTime(0, 1, (s) => s.airborne && s.away === 0);
  const s = uav(t, 0);
  const page = await openAt(html, t);
  const row = await uavRow(page, 0);
  assert.equal(row.battery, `${s.battery} s`);
  assert.equal(row.width, `${(100 * s.battery / 600).toFixed(1)}%`);
  assert.ok(s.battery > trace.battery.reserve_steps);
  assert.equal(row.color, BATTERY_OK);
  await page.close();

  // The same trace with the reserve at UAV 0's battery at t: its gauge turns red there.
  const low = structuredClone(trace);
  low.battery.reserve_steps = s.battery;
  const lowPath = path.join(OUT, 'sorties-reserve.json');
  fs.writeFileSync(lowPath, JSON.stringify(low));
  const lowHtml = path.join(OUT, 'sorties-reserve.html');
  cli(['view', lowPath, '--out', lowHtml]);
  const lowPage = await openAt(lowHtml, t);
  assert.equal((await uavRow(lowPage, 0)).color, BATTERY_LOW);
  await lowPage.close();
});

test('a trace of the paper\'s model has neither the flight nor the battery column', async () => {
  const plainTrace = path.join(OUT, 'plain.json');
  const plainHtml = path.join(OUT, 'plain.html');
  cli(['run', '--uavs', '2', '--seed', '2', '--trace', plainTrace, '--html', plainHtml]);
  const {page} = await browser.open(plainHtml);
  assert.deepEqual(await page.$$eval('#uav-table thead th', (th) => th.map((h) => h.textContent)),
                   ['UAV', 'cell', 'plane', 'mode', 'target']);
  assert.equal(await page.$$eval('.gauge', (g) => g.length), 0);
  await page.close();
});

test('the 3D view draws no UAV on the ground or away on the hull, nor its line of sight', async () => {
  // The DTC hull (a mesh, so a 3D view), 8 UAVs from two sites on the quay, batteries of 1500 s.
  const dtcTrace = path.join(OUT, 'dtc-sorties.json');
  const dtcHtml = path.join(OUT, 'dtc-sorties.html');
  cli(['run', '--hull', 'dtc', '-a', 'sweep-inspect', '-n', '8', '--seed', '1', '--launch', '186,0',
       '--launch', '559,0', '--endurance', '1500', '--swap-time', '90', '--trace', dtcTrace]);
  cli(['view', dtcTrace, '--3d', '--out', dtcHtml]);
  const dtc = JSON.parse(fs.readFileSync(dtcTrace, 'utf8'));
  const offHull = (t) => Array.from({length: 8}, (_, k) => {
    const u = dtc.frames[t].u.slice(FIELDS * k, FIELDS * (k + 1));
    return u[5] === 0 || u[7] > 0;
  });
  // At t = 0 every UAV is on the ground; later some work on the hull while others swap.
  const mixed = dtc.frames.findIndex((f, t) => new Set(offHull(t)).size === 2);
  assert.ok(mixed > 0, 'no time with UAVs both on and off the hull');
  const {page} = await browser.open(dtcHtml);
  for (const t of [0, mixed]) {
    await seek(page, t);
    const shown = await page.evaluate(() => window.hullViewer.view3d().uavs.map((u) => [u.mesh.visible, u.sight.visible]));
    offHull(t).forEach((off, k) => {
      assert.equal(shown[k][0], !off, `t = ${t}: UAV ${k} ${off ? 'off' : 'on'} the hull`);
      if (off) assert.equal(shown[k][1], false, `t = ${t}: UAV ${k}'s line of sight drawn`);
    });
  }
  await page.screenshot({path: path.join(OUT, 'dtc-sorties-3d.png')});
  await page.close();
});
