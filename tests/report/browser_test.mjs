// Browser test of `planarbench report` (SPEC §6): runs the falling_ball case
// on every engine, writes the report, opens report.html in Debian's headless
// Chromium through playwright-core, and checks that the page renders without
// a console error or page error, fetches nothing, and that every chart holds
// data from every engine whose run is ok. Saves a screenshot of the
// falling-ball force figure (paper Fig. 5) next to the test.
//
// Usage: node browser_test.mjs --planarbench EXE --web-dir DIR --work DIR
// Needs node >= 20, the npm packages of reports/web (scripts/setup_web.sh
// installs them) and /usr/bin/chromium (scripts/setup_web.sh installs it).
import { spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const SETUP = 'run scripts/setup_web.sh (it installs Debian\'s chromium and the pinned npm packages)';
const CHROMIUM = '/usr/bin/chromium';
const ENGINES = ['analytic', 'reference', 'mujoco', 'box2d', 'ode'];

let failures = 0;
function check(ok, what) {
  console.log((ok ? 'ok   ' : 'FAIL ') + what);
  if (!ok) failures++;
  return ok;
}
function fatal(message) {
  console.error('FAIL ' + message);
  console.log('0 passed, 1 failed');
  process.exit(1);
}

// ---- arguments and prerequisites ----------------------------------------------
const args = {};
for (let i = 2; i < process.argv.length; i += 2) args[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
for (const k of ['planarbench', 'web-dir', 'work']) {
  if (!args[k]) fatal(`missing --${k}; usage: node browser_test.mjs --planarbench EXE --web-dir DIR --work DIR`);
}
const major = Number(process.versions.node.split('.')[0]);
if (major < 20) fatal(`node ${process.versions.node} is too old (playwright-core needs >= 20): ${SETUP}`);
if (!fs.existsSync(CHROMIUM)) fatal(`${CHROMIUM} not found: ${SETUP}`);
let chromium;
try {
  const require = createRequire(path.join(path.resolve(args['web-dir']), 'package.json'));
  ({ chromium } = require('playwright-core'));
} catch (e) {
  fatal(`playwright-core not found under ${args['web-dir']}/node_modules: ${SETUP} (${e.message})`);
}

// ---- run the case and write the report ----------------------------------------------
const work = path.resolve(args.work);
fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(work, { recursive: true });
const results = path.join(work, 'falling_ball.h5');
const reportDir = path.join(work, 'report');

function run(argv, okCodes) {
  const r = spawnSync(args.planarbench, argv, {
    encoding: 'utf8',
    env: { ...process.env, PLANARBENCH_WEB_DIR: path.resolve(args['web-dir']) },
  });
  if (r.error) fatal(`cannot start ${args.planarbench}: ${r.error.message}`);
  process.stdout.write(r.stdout);
  process.stdout.write(r.stderr);
  if (!okCodes.includes(r.status)) fatal(`planarbench ${argv.join(' ')} exited ${r.status}`);
  return r;
}
// exit 3 (a run diverged) still writes the file: the report must show it
run(['run', '--case', 'falling_ball', '--engine', ENGINES.join(','), '--out', results, '--quiet'], [0, 3]);
run(['report', results, '--out', reportDir], [0]);
const html = path.join(reportDir, 'report.html');
check(fs.existsSync(html), 'report.html written');
check(fs.existsSync(path.join(reportDir, 'report.md')), 'report.md written');
check(fs.existsSync(path.join(reportDir, 'figures', 'falling_ball_fig5.svg')), 'figures/falling_ball_fig5.svg written');

// the engines whose run is ok, read from the results file with h5py (not
// from the page under test)
const py = spawnSync('/usr/bin/python3', ['-c', [
  'import h5py, sys, json',
  'f = h5py.File(sys.argv[1], "r")',
  'g = f["runs/falling_ball"]',
  'print(json.dumps({e: str(g[e].attrs["status"]) for e in g}))',
].join('\n'), results], { encoding: 'utf8' });
if (py.status !== 0) fatal(`cannot read the run statuses with h5py (scripts/setup.sh installs python3-h5py): ${py.stderr}`);
const statuses = JSON.parse(py.stdout);
const okEngines = Object.keys(statuses).filter((e) => statuses[e] === 'ok');
console.log('run statuses: ' + JSON.stringify(statuses));
check(okEngines.length > 0, 'at least one engine ran falling_ball ok');

// ---- open the page in headless Chromium -------------------------------------
const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'pb-chromium-'));
let context;
try {
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: CHROMIUM,
    headless: true,
    viewport: { width: 1280, height: 900 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
} catch (e) {
  fs.rmSync(userDataDir, { recursive: true, force: true });
  fatal(`cannot launch ${CHROMIUM}: ${e.message}; ${SETUP}`);
}
const consoleErrors = [];
const pageErrors = [];
const foreignRequests = [];
const pageUrl = pathToFileURL(html).href;
try {
  // the page is self-contained: anything but the page itself is a failure
  await context.route('**/*', (route) => {
    const url = route.request().url();
    if (url === pageUrl) return route.continue();
    foreignRequests.push(url);
    return route.abort();
  });
  const page = context.pages()[0] || await context.newPage();
  page.on('console', (msg) => { if (msg.type() === 'error') consoleErrors.push(msg.text()); });
  page.on('pageerror', (err) => pageErrors.push(String(err)));
  await page.goto(pageUrl, { waitUntil: 'load' });
  await page.waitForFunction(() => window.planarbenchReport !== undefined, null, { timeout: 60000 });
  const report = await page.evaluate(() => window.planarbenchReport);

  // every chart holds data from every engine whose run is ok
  check(report.charts.length >= 2, `page has ${report.charts.length} charts (falling_ball: Figs 5 and 6 at least)`);
  for (const chart of report.charts) {
    for (const engine of okEngines) {
      const s = chart.series.find((x) => x.engine === engine);
      check(s !== undefined && s.points > 0,
        `chart ${chart.id}: ${engine} has ${s ? s.points : 0} points`);
    }
    for (const s of chart.series) {
      check(okEngines.includes(s.engine), `chart ${chart.id}: series ${s.engine} is of an ok run`);
    }
  }
  const fig5 = report.charts.find((c) => c.id === 'falling_ball_fig5');
  check(fig5 !== undefined && fig5.title.startsWith('Fig. 5'), 'falling_ball Fig. 5 (contact force) is on the page');

  // tables are there
  for (const id of ['capability', 'timings', 'metrics', 'provenance']) {
    const rows = await page.locator(`#tbl-${id} tbody tr`).count();
    check(rows > 0, `table ${id} has ${rows} rows`);
  }

  // the force figure, whole and zoomed into the first contact episode
  const figure = page.locator('#fig-falling_ball_fig5');
  await figure.scrollIntoViewIfNeeded();
  const png = path.join(path.dirname(work), 'falling_ball_fig5.png');
  await figure.screenshot({ path: png });
  // > 10 kB: a blank PNG of this size compresses to well under 1 kB, so a
  // larger file means something was drawn
  check(fs.statSync(png).size > 10000, `screenshot ${png}`);
  const zoom = figure.getByRole('button', { name: 'zoom to episode 1' });
  check(await zoom.count() === 1, 'Fig. 5 has a "zoom to episode 1" button');
  if (await zoom.count() === 1) {
    await zoom.click();
    await page.waitForTimeout(200);
    const zpng = path.join(path.dirname(work), 'falling_ball_fig5_episode1.png');
    await figure.screenshot({ path: zpng });
    check(fs.statSync(zpng).size > 10000, `screenshot ${zpng}`);
  }
} finally {
  await context.close();
  fs.rmSync(userDataDir, { recursive: true, force: true });
}
check(consoleErrors.length === 0, `no console errors${consoleErrors.length ? ': ' + consoleErrors.join(' | ') : ''}`);
check(pageErrors.length === 0, `no page errors${pageErrors.length ? ': ' + pageErrors.join(' | ') : ''}`);
check(foreignRequests.length === 0, `no requests beyond the page${foreignRequests.length ? ': ' + foreignRequests.join(' ') : ''}`);

console.log(failures === 0 ? 'browser test passed' : `browser test: ${failures} check(s) failed`);
process.exit(failures === 0 ? 0 : 1);
