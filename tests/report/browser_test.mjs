// Browser test of `planarbench report` (SPEC §6): runs the falling_ball case
// (closed-form truth) and falling_ball_paper (no truth) on every engine,
// writes the report, opens report.html in Debian's headless Chromium through
// playwright-core, and checks that the page renders without a console error
// or page error, fetches nothing, and that every chart holds data from every
// engine whose run is ok. At 1440x900 and 390x844 (issue 13): no horizontal
// overflow, the verdict in the first screen naming each case's best engine
// and every ok engine's error, which must match the largest position error
// computed here with h5py from the results file. Saves screenshots of the
// first screen at both sizes and of the falling-ball force figure (paper
// Fig. 5) next to the test. Then a small campaign's report (issue 14): every
// figure of its Markdown drawn on the page, its tables, no overflow.
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
const ENGINES = ['analytic', 'reference', 'mujoco', 'mujoco3', 'box2d', 'ode'];

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
// a closed-form truth, no truth, a truth that is the converged reference
// after the first impact (issue 13: drawn through the impacts), and a block
// that friction holds (issue 22: the friction section's drift figure)
const CASES = ['falling_ball', 'falling_ball_paper', 'dual_pendulum', 'block_hold'];
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
run(['run', '--case', CASES.join(','), '--engine', ENGINES.join(','), '--out', results, '--quiet'], [0, 3]);
// the friction curve (issue 22) beside the results: the friction section's curve
const frictionCurve = path.join(path.resolve(args['web-dir']), '..', '..', 'campaigns', 'friction_curve.toml');
run(['campaign', 'run', frictionCurve, '--out', path.join(work, 'friction_curve'), '--quiet'], [0]);
run(['campaign', 'merge', path.join(work, 'friction_curve'), '--out', path.join(work, 'friction_curve.h5'), '--quiet'], [0]);
// the block family (issue 30): its three figures and table in the friction section
const blockFamily = path.join(path.resolve(args['web-dir']), '..', '..', 'campaigns', 'block_family.toml');
run(['campaign', 'run', blockFamily, '--out', path.join(work, 'block_family'), '--jobs', '2', '--quiet'], [0]);
run(['campaign', 'merge', path.join(work, 'block_family'), '--out', path.join(work, 'block_family.h5'), '--quiet'], [0]);
// measured impacts (issue 23): a small file written by scipy (tests/impacts/
// write_mat.py), fitted on Box2D (the cheapest engine), beside the results
const impactsMat = path.join(work, 'impacts.mat');
const writeMat = spawnSync('/usr/bin/python3', [path.join(path.resolve(args['web-dir']), '..', '..', 'tests', 'impacts', 'write_mat.py'),
  impactsMat, '60', '4', '0.6', '0.2', '--models'], { encoding: 'utf8' });
if (writeMat.status !== 0) fatal(`write_mat.py failed: ${writeMat.stderr}`);
run(['impacts', 'fit', '--data', impactsMat, '--engine', 'box2d', '--folds', '2', '--max-evaluations', '3',
  '--out', path.join(work, 'impacts_fit.h5'), '--quiet'], [0]);
// each model's median e_F, by numpy from the file's e_f column (issue 34)
const efPy = spawnSync('/usr/bin/python3', ['-c', [
  'import h5py, json, numpy as np, sys',
  'r = h5py.File(sys.argv[1], "r")["campaign"]["runs"]',
  'eng = np.array([e.decode() if isinstance(e, bytes) else str(e) for e in r["engine"][()]])',
  'ef = np.asarray(r["metric"]["e_f"][()], dtype=float)',
  'print(json.dumps({e: float(np.median(ef[eng == e])) for e in sorted(set(eng)) if np.all(np.isfinite(ef[eng == e]))}))',
].join('\n'), path.join(work, 'impacts_fit.h5')], { encoding: 'utf8' });
if (efPy.status !== 0) { console.error(efPy.stderr); process.exit(1); }
const impactsEf = JSON.parse(efPy.stdout);
run(['report', results, '--campaign', path.join(work, 'friction_curve.h5'),
  '--campaign', path.join(work, 'block_family.h5'), '--impacts', path.join(work, 'impacts_fit.h5'),
  '--out', reportDir], [0]);
const reportMd = fs.readFileSync(path.join(reportDir, 'report.md'), 'utf8');
const frictionStart = reportMd.indexOf('## Friction');
const frictionEnd = reportMd.indexOf('\n## ', frictionStart + 1);
const frictionSection = reportMd.slice(frictionStart, frictionEnd < 0 ? undefined : frictionEnd);
const frictionFigures = (frictionSection.match(/!\[[^\]]*\]\(figures\/[^)]+\.svg\)/g) || []).length;
check(frictionFigures === 5, `report.md's friction section has 5 figures (block_hold's drift, the friction curve, the block family's three): ${frictionFigures}`);
check(frictionSection.includes('### Block family'), "report.md's friction section has the block family's table");
// the physical-validity section (issue 32): block_hold's Coulomb and creep
// figures, the normal-law residual of the three frictionless cases
const validityStart = reportMd.indexOf('## Physical validity');
const validityEnd = reportMd.indexOf('\n## ', validityStart + 1);
const validitySection = validityStart < 0 ? '' : reportMd.slice(validityStart, validityEnd < 0 ? undefined : validityEnd);
const validityFigures = (validitySection.match(/!\[[^\]]*\]\(figures\/[^)]+\.svg\)/g) || []).length;
check(validityFigures === 5, `report.md's physical-validity section has 5 figures (block_hold's Coulomb distance and creep, the law residual of falling_ball, falling_ball_paper, dual_pendulum): ${validityFigures}`);
const html = path.join(reportDir, 'report.html');
check(fs.existsSync(html), 'report.html written');

// a small campaign (issue 14) and its report: the campaign section renders
// every figure the Markdown has, without overflow, at both sizes
const campaignToml = path.join(work, 'campaign.toml');
fs.writeFileSync(campaignToml, [
  '[campaign]', 'cases = ["falling_ball"]', 'engines = ["mujoco", "ode"]',
  'metrics = ["position_error_m", "first_restitution", "trace"]', 'trace_points = 20',
  '[[axis]]', 'key = "dt"', 'values = [1e-3, 1e-4]',
  '[[axis]]', 'name = "state"', 'key = "bodies.*.velocity"', 'perturb = { sigma = 1e-2, samples = 3, seed = 2 }', ''].join('\n'));
run(['campaign', 'run', campaignToml, '--out', path.join(work, 'campaign'), '--quiet'], [0]);
run(['campaign', 'merge', path.join(work, 'campaign'), '--out', path.join(work, 'campaign.h5'), '--quiet'], [0]);
run(['report', path.join(work, 'campaign.h5'), '--out', path.join(work, 'campaign_report')], [0]);
const campaignHtml = path.join(work, 'campaign_report', 'report.html');
const campaignMd = fs.readFileSync(path.join(work, 'campaign_report', 'report.md'), 'utf8');
const campaignFigures = (campaignMd.match(/!\[[^\]]*\]\(figures\/[^)]+\.svg\)/g) || []).length;
check(campaignFigures === 4, `campaign report.md has 4 figures (error and wall time against dt, spread at each dt): ${campaignFigures}`);
check(fs.existsSync(path.join(reportDir, 'report.md')), 'report.md written');
check(fs.existsSync(path.join(reportDir, 'figures', 'falling_ball_fig5.svg')), 'figures/falling_ball_fig5.svg written');

// the engines whose run is ok, read from the results file with h5py (not
// from the page under test)
// and each ok engine's largest position error against the case's yardstick
// (the analytic run where there is one, else the reference), on the common
// output grid: the truth the verdict's numbers are checked against
const casesDir = path.join(path.resolve(args['web-dir']), '..', '..', 'cases');
const py = spawnSync('/usr/bin/python3', ['-c', [
  'import h5py, sys, json, tomllib',
  'import numpy as np',
  `cases_dir = ${JSON.stringify(casesDir)}`,
  'f = h5py.File(sys.argv[1], "r")',
  'out = {}',
  'for case in sys.argv[2:]:',
  '    g = f["runs/" + case]',
  '    st = {e: str(g[e].attrs["status"]) for e in g}',
  '    base = "analytic" if st.get("analytic") == "ok" else "reference"',
  '    err = {}',
  '    for e in g:',
  '        if e in ("analytic", base) or st[e] != "ok": continue',
  '        worst = 0.0',
  '        for b in g[base]["bodies"]:',
  '            tb = g[base]["bodies"][b]["time"][:]; pb = g[base]["bodies"][b]["position"][:]',
  '            te = g[e]["bodies"][b]["time"][:]; pe = g[e]["bodies"][b]["position"][:]',
  '            n = min(len(tb), len(te))',
  '            assert np.allclose(tb[:n], te[:n], rtol=0, atol=1e-12), "grids differ"',
  '            worst = max(worst, float(np.max(np.linalg.norm(pe[:n] - pb[:n], axis=1))))',
  '        err[e] = worst',
  '    ev = g["reference"]["events"]',
  '    onset = float(ev[0]["onset_time"]) if ev.shape[0] else None',
  '    peaks = {e: max([float(x) for x in g[e]["events"]["peak_force"]] or [0.0]) for e in g if st[e] == "ok"}',
  '    out[case] = {"status": st, "base": base, "error": err, "first_onset": onset, "peak_force": peaks}',
  // issue 32: each engine's cone violation and stick creep on block_hold,
  // from the contacts columns and the case file's mu (SPEC §9), formatted as
  // the report prints them (%.2g); and the rows the validity table has
  '    pairs = tomllib.load(open(cases_dir + "/" + case + ".toml", "rb")).get("contacts", [])',
  '    mu = pairs[0].get("friction", 0.0) if pairs else 0.0',
  '    out[case]["contact_rows"] = {e: int(g[e]["contacts"].shape[0]) for e in g if e != "analytic" and st[e] != "unsupported" and "contacts" in g[e]}',
  '    if mu > 0:',
  '        val = {}',
  '        for e in g:',
  '            if e == "analytic" or st[e] == "unsupported": continue',
  '            c = g[e]["contacts"][:]',
  '            fn, ft, v = c["force_n"], c["tangential_force_n"], c["slip_mps"]',
  '            ok = np.isfinite(ft) & np.isfinite(v) & (fn > 0)',
  '            lim = mu * fn[ok]',
  '            cone = np.maximum(0.0, np.abs(ft[ok]) - lim) / lim',
  '            inside = (np.abs(v[ok]) <= 1e-3) & (np.abs(ft[ok]) <= (1 - 1e-3) * lim)',
  '            creep = np.abs(v[ok][inside])',
  '            val[e] = {"cone": format(float(cone.max()), ".2g") if cone.size else "-",',
  '                      "creep": format(float(creep.max()), ".2g") if creep.size else "-"}',
  '        out[case]["validity"] = val',
  'print(json.dumps(out))',
].join('\n'), results, ...CASES], { encoding: 'utf8' });
if (py.status !== 0) fatal(`cannot read the runs with h5py (scripts/setup.sh installs python3-h5py): ${py.stderr}`);
const truthOf = JSON.parse(py.stdout);
const statuses = truthOf.falling_ball.status;
const okEngines = Object.keys(statuses).filter((e) => statuses[e] === 'ok');
console.log('run statuses: ' + JSON.stringify(statuses));
check(okEngines.length > 0, 'at least one engine ran falling_ball ok');

// ---- waiting on conditions, not on time ---------------------------------------
// Every wait is for something the page publishes, with a generous overall
// limit (a busy machine is slow, not wrong): WAIT_MS, then the check fails.
const WAIT_MS = 60000;
// one painted frame after the page's last change (two rAF callbacks: the
// second runs after the first frame's paint)
async function painted(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}
// sets the viewport and waits for the charts' resize redraw (report.js counts
// them on <html data-resizes>, 150 ms after the last resize event) and a frame
async function resizeTo(page, width, height) {
  const [w, h, before] = await page.evaluate(() => [window.innerWidth, window.innerHeight,
    Number(document.documentElement.dataset.resizes || 0)]);
  await page.setViewportSize({ width, height });
  if (w !== width || h !== height) {
    await page.waitForFunction((n) => Number(document.documentElement.dataset.resizes || 0) > n,
      before, { timeout: WAIT_MS });
  }
  await painted(page);
}

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
  const campaignUrl = pathToFileURL(campaignHtml).href;
  await context.route('**/*', (route) => {
    const url = route.request().url();
    if (url === pageUrl || url === campaignUrl) return route.continue();
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
  // a chart's case: the longest case name its id starts with
  const byLength = [...CASES].sort((a, b) => b.length - a.length);
  for (const chart of report.charts) {
    const c = byLength.find((name) => chart.id.startsWith(name + '_'));
    if (!check(c !== undefined, `chart ${chart.id} belongs to a case that ran`)) continue;
    const st = truthOf[c].status;
    const ok = Object.keys(st).filter((e) => st[e] === 'ok');
    for (const engine of ok) {
      const s = chart.series.find((x) => x.engine === engine);
      check(s !== undefined && s.points > 0,
        `chart ${chart.id}: ${engine} has ${s ? s.points : 0} points`);
    }
    for (const s of chart.series) {
      check(ok.includes(s.engine), `chart ${chart.id}: series ${s.engine} is of an ok run`);
    }
  }
  // every reproduced paper figure has an error panel with data, and the
  // dual pendulum's truth is drawn past its first impact
  const paperFigures = report.charts.filter((c) => c.paperFigure);
  check(paperFigures.length >= 6, `${paperFigures.length} reproduced paper figures (falling_ball 2, dual_pendulum 4 at least)`);
  for (const chart of paperFigures) {
    const e = chart.errorPanel;
    check(e !== null && e.series.some((s) => s.points > 0),
      `${chart.id} (${chart.paperFigure}): error panel against the ${e ? e.against : '-'} with ${e ? e.series.map((s) => s.engine + ' ' + s.points).join(', ') : 'no'} points`);
  }
  const onset = truthOf.dual_pendulum.first_onset;
  for (const chart of report.charts.filter((c) => c.id.startsWith('dual_pendulum_'))) {
    const truth = chart.series.find((s) => s.engine === 'analytic');
    check(truth !== undefined && onset !== null && truth.tLast > onset + 0.1,
      `${chart.id}: the truth is drawn past the first impact (to t = ${truth ? truth.tLast : '-'} s; onset ${onset} s)`);
  }

  // the dual pendulum's 0.24 ms pulse is drawn through its peak: each
  // compliant engine's plotted maximum within 1 % of its episodes' peak force
  // (Box2D's rigid impact lasts one step between output samples: not drawn)
  const pulse = report.charts.find((c) => c.id === 'dual_pendulum_force_ellipse_disk');
  if (check(pulse !== undefined, 'dual_pendulum force figure is on the page')) {
    for (const s of pulse.series.filter((x) => x.engine !== 'box2d')) {
      const want = truthOf.dual_pendulum.peak_force[s.engine];
      check(s.peak !== null && Math.abs(s.peak - want) <= 0.01 * want,
        `dual_pendulum pulse: ${s.engine} plotted peak ${s.peak} N, its episodes' peak ${want.toPrecision(6)} N`);
    }
  }

  const fig5 = report.charts.find((c) => c.id === 'falling_ball_fig5');
  check(fig5 !== undefined && fig5.title.startsWith('Fig. 5'), 'falling_ball Fig. 5 (contact force) is on the page');

  // the friction section (issue 22): its two figures drawn, the curve's 11 points tabulated
  const frictionPlots = await page.locator('#friction .wp-plot svg').count();
  check(frictionPlots === frictionFigures, `friction section draws its ${frictionFigures} figures: ${frictionPlots}`);
  const curveRows = await page.locator('#friction table').first().locator('tbody tr').count();
  check(curveRows === 11, `friction curve table has a row per tan(theta) / mu from 0.5 to 1.5: ${curveRows}`);
  const familyRows = await page.locator('#friction table').nth(1).locator('tbody tr').count();
  check(familyRows === 4, `block family table has a row per engine of the campaign: ${familyRows}`);

  // the measured-impacts section (issue 23): its convention, models and fits
  // tables, its four figures (the CDF of eps, predicted against measured x', y', theta')
  // issue 33: MuJoCo 2.2.2 and 3.3.8 side by side, one row per case with both
  const versionRows = await page.evaluate(() => [...document.querySelectorAll('#tbl-mujoco_versions tbody tr')]
    .map((tr) => [...tr.cells].map((td) => td.textContent.trim())));
  check(versionRows.length === CASES.length,
    `the MuJoCo versions table has a row per case (${versionRows.length} of ${CASES.length})`);
  const ball = versionRows.find((r) => r[0] === 'falling_ball');
  // falling_ball: one sphere-plane contact, computed alike by both versions (mujoco3_engine_test)
  check(ball !== undefined && Number(ball[1]) > 0 && ball[1] === ball[2],
    `falling_ball: every metric the same in 2.2.2 and 3.3.8 (${ball ? ball[2] + ' of ' + ball[1] : 'no row'})`);
  const impactPlots = await page.locator('#impacts .wp-plot svg').count();
  check(impactPlots === 4, `measured-impacts section draws its 4 figures: ${impactPlots}`);
  const impactTables = await page.locator('#impacts table').count();
  check(impactTables === 4, `measured-impacts section has its 4 tables: ${impactTables}`);
  // what the data identify (issue 34): a row per fitted parameter of the fitted
  // models: box2d's zeta and mu (its K is fixed), rigid's e and mu, rigid_compliant's five,
  // the naive bounce's e (learned_residual has no parameter of the fit's)
  const spreadRows = await page.locator('#tbl-impacts_identification tbody tr').count();
  check(spreadRows === 10, `the identification table has a row per fitted parameter: ${spreadRows}`);
  const conventionRows = await page.locator('#impacts table').first().locator('tbody tr').count();
  check(conventionRows === 4, `the convention table has a row per sign pair: ${conventionRows}`);
  // both metrics (issue 34): each model's e_F median as numpy gives it from
  // the fit file's e_f column (h5py), beside eps
  const modelTable = await page.evaluate(() => {
    const t = document.querySelector('#tbl-impacts_models');
    if (!t) return null;
    return { head: [...t.querySelectorAll('thead th')].map((th) => th.textContent),
      rows: [...t.querySelectorAll('tbody tr')].map((tr) => [...tr.querySelectorAll('td')].map((td) => td.textContent)) };
  });
  if (check(modelTable !== null, 'the impacts models table is there')) {
    const col = modelTable.head.indexOf('e_F median');
    check(col > 0 && modelTable.head.includes('eps median') && modelTable.head.includes('spin eps median'),
      `the models table shows eps, e_F and the spin's error: ${modelTable.head.join(' | ')}`);
    for (const [model, want] of Object.entries(impactsEf)) {
      const row = modelTable.rows.find((r) => r[0] === model);
      if (!check(row !== undefined, `models table has ${model}`)) continue;
      check(row[col] === want.toFixed(4), `${model}: e_F median ${row[col]} against numpy's ${want.toFixed(4)}`);
    }
  }

  // the physical-validity section (issue 32): its figures, a row per run and
  // pair with contact rows, and block_hold's cone and creep as h5py and the
  // case's mu give them
  const validityPlots = await page.locator('#validity .wp-plot svg').count();
  check(validityPlots === validityFigures, `physical-validity section draws its ${validityFigures} figures: ${validityPlots}`);
  const wantRows = CASES.reduce((n, c) => n + Object.values(truthOf[c].contact_rows).filter((k) => k > 0).length, 0);
  const validityRows = await page.evaluate(() => [...document.querySelectorAll('#tbl-validity tbody tr')]
    .map((tr) => [...tr.querySelectorAll('td')].map((td) => td.textContent)));
  check(validityRows.length === wantRows, `validity table has a row per run with contact rows: ${validityRows.length} of ${wantRows}`);
  const readings = await page.locator('#validity ul.readings li').count();
  check(readings >= 1, `validity readings: ${readings} engine lines`);
  for (const [engine, want] of Object.entries(truthOf.block_hold.validity || {})) {
    const row = validityRows.find((r) => r[0] === 'block_hold' && r[1] === engine);
    if (!check(row !== undefined, `validity table has block_hold x ${engine}`)) continue;
    const first = (cell) => cell.split(' (')[0];
    check(first(row[4]) === want.cone && first(row[6]) === want.creep,
      `block_hold x ${engine}: cone ${row[4]}, creep ${row[6]} against h5py's ${want.cone}, ${want.creep}`);
  }

  // tables are there
  for (const id of ['capability', 'timings', 'metrics', 'provenance']) {
    const rows = await page.locator(`#tbl-${id} tbody tr`).count();
    check(rows > 0, `table ${id} has ${rows} rows`);
  }

  // the first screen at a laptop's and a phone's size
  for (const [width, height] of [[1440, 900], [390, 844]]) {
    await resizeTo(page, width, height);
    await page.evaluate(() => window.scrollTo(0, 0));
    await painted(page);
    const size = `${width}x${height}`;
    const layout = await page.evaluate(() => {
      const v = document.getElementById('table-verdict');
      const box = v ? v.getBoundingClientRect() : null;
      const rows = v ? [...v.querySelectorAll('tbody tr')].map((tr) =>
        [...tr.querySelectorAll('td')].map((td) => td.textContent)) : [];
      return {
        scrollWidth: document.documentElement.scrollWidth,
        innerWidth: window.innerWidth,
        innerHeight: window.innerHeight,
        top: box ? box.top : null,
        bottom: box ? box.bottom : null,
        rows,
      };
    });
    check(layout.scrollWidth <= layout.innerWidth,
      `${size}: no horizontal overflow (page ${layout.scrollWidth} px wide in ${layout.innerWidth} px)`);
    // the friction figures fit the width and are drawn (a box with an area)
    const friction = await page.evaluate(() => [...document.querySelectorAll('#friction .wp-plot svg')]
      .map((svg) => { const b = svg.getBoundingClientRect(); return [b.width, b.height, b.right]; }));
    check(friction.length === 5 && friction.every(([w, h, right]) => w > 100 && h > 50 && right <= layout.innerWidth),
      `${size}: friction figures drawn within the width (${JSON.stringify(friction.map((f) => f.map(Math.round)))})`);
    const validity = await page.evaluate(() => [...document.querySelectorAll('#validity .wp-plot svg')]
      .map((svg) => { const b = svg.getBoundingClientRect(); return [b.width, b.height, b.right]; }));
    check(validity.length === validityFigures && validity.every(([w, h, right]) => w > 100 && h > 50 && right <= layout.innerWidth),
      `${size}: physical-validity figures drawn within the width (${JSON.stringify(validity.map((f) => f.map(Math.round)))})`);
    check(layout.top !== null && layout.top >= 0 && layout.top < layout.innerHeight,
      `${size}: the verdict starts in the first screen (top at ${layout.top} px)`);
    // a laptop sees the whole verdict without scrolling
    if (width >= 1440) {
      check(layout.bottom !== null && layout.bottom <= layout.innerHeight,
        `${size}: the whole verdict is in the first screen (bottom at ${layout.bottom} px)`);
    }
    const shot = path.join(path.dirname(work), `report_first_screen_${size}.png`);
    await page.screenshot({ path: shot });
    check(fs.statSync(shot).size > 10000, `screenshot ${shot}`);
    if (width !== 1440) continue;
    // the verdict's numbers against h5py's: each case names its best engine
    // and every ok engine's error, two significant digits as printed
    for (const c of CASES) {
      const row = layout.rows.find((r) => r[0] === c);
      if (!check(row !== undefined, `verdict has a row for ${c}`)) continue;
      const errs = truthOf[c].error;
      const engines = Object.keys(errs);
      const best = engines.reduce((a, b) => (errs[b] < errs[a] ? b : a), engines[0]);
      check(row[2] === best, `verdict ${c}: best engine ${row[2]} (h5py: ${best}, ${errs[best]} m)`);
      for (const e of engines) {
        const m = row[3].match(new RegExp(`(?:^|; )${e} ([0-9.e+-]+) \\(`));
        const shown = m ? Number(m[1]) : NaN;
        // the page prints two significant digits: within half a unit of the
        // second digit, 5 % of the value
        check(Math.abs(shown - errs[e]) <= 0.05 * errs[e],
          `verdict ${c}: ${e} error ${m ? m[1] : 'missing'} m (h5py ${errs[e].toPrecision(3)} m against ${truthOf[c].base})`);
      }
      if (truthOf[c].base !== 'analytic') {
        check(/no truth/.test(row[4]), `verdict ${c}: flagged as measured against the reference, not a truth`);
      }
    }
  }
  await resizeTo(page, 1280, 900);

  // the force figure, whole and zoomed into the first contact episode
  const figure = page.locator('#fig-falling_ball_fig5');
  await figure.scrollIntoViewIfNeeded();
  const png = path.join(path.dirname(work), 'falling_ball_fig5.png');
  await figure.screenshot({ path: png });
  // > 10 kB: a blank PNG of this size compresses to well under 1 kB, so a
  // larger file means something was drawn
  check(fs.statSync(png).size > 10000, `screenshot ${png}`);
  const zoom = figure.getByRole('button', { name: 'zoom to episode 0' });
  check(await zoom.count() === 1, 'Fig. 5 has a "zoom to episode 0" button');
  if (await zoom.count() === 1) {
    // the zoom redraws the figure (report.js counts its draws on data-draws)
    const draws = Number(await figure.getAttribute('data-draws'));
    await zoom.click();
    await page.waitForFunction((n) => Number(document.getElementById('fig-falling_ball_fig5').dataset.draws) > n,
      draws, { timeout: WAIT_MS });
    await painted(page);
    const zpng = path.join(path.dirname(work), 'falling_ball_fig5_episode0.png');
    await figure.screenshot({ path: zpng });
    check(fs.statSync(zpng).size > 10000, `screenshot ${zpng}`);
  }

  // the campaign's page
  await page.goto(campaignUrl, { waitUntil: 'load' });
  await page.waitForSelector('#campaign', { timeout: 60000 });
  const plots = await page.locator('#campaign .wp-plot svg').count();
  check(plots === campaignFigures, `campaign page draws its ${campaignFigures} figures: ${plots}`);
  const tables = await page.locator('#campaign table').count();
  check(tables >= 3, `campaign page has its tables (runs, against dt, spread): ${tables}`);
  for (const [width, height] of [[1440, 900], [390, 844]]) {
    await resizeTo(page, width, height);
    const w = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
    check(w[0] <= w[1], `campaign page ${width}x${height}: no horizontal overflow (${w[0]} px in ${w[1]} px)`);
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
