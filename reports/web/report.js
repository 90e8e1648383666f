// planarbench report page: renders the embedded report data (JSON in
// #pb-data) into figures (uPlot) and tables. Every text goes in through
// textContent, never as HTML. When the charts are drawn it publishes
// window.planarbenchReport = { charts: [{ id, title, paperFigure,
//   series: [{ engine, points, tLast, peak }], errorPanel: { against, series } | null }] }
// for the browser test (tests/report/browser_test.mjs).
(function () {
  'use strict';

  const data = JSON.parse(document.getElementById('pb-data').textContent);

  // element helper: el('p', {class: 'x'}, 'text', child, ...)
  function el(tag, attrs, ...children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'class') e.className = v;
      else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
      else e.setAttribute(k, v);
    }
    for (const c of children) {
      if (c === null || c === undefined) continue;
      e.appendChild(typeof c === 'string' ? document.createTextNode(c) : c);
    }
    return e;
  }

  function slug(text) {
    return String(text).toLowerCase().replace(/[^a-z0-9_-]+/g, '-');
  }

  // ---- header and navigation ------------------------------------------------
  function renderHeader() {
    const h = document.getElementById('pb-header');
    h.appendChild(el('h1', {}, 'planarbench report'));
    // the inputs on one line
    const files = el('p', {});
    for (const [label, file] of [['Results file', data.results_file], ['sweep file', data.sweep_file],
      ['campaign file', data.campaign && data.campaign.file],
      ['measured impacts', data.impacts && data.impacts.file], ['thresholds', data.thresholds_file]]) {
      if (!file) continue;
      if (files.childNodes.length) files.appendChild(document.createTextNode('; '));
      files.appendChild(document.createTextNode(label + ': '));
      files.appendChild(el('code', {}, file));
    }
    if (files.childNodes.length) h.appendChild(files);
    if (data.check_summary) {
      const failed = !data.check_summary.startsWith('gate passed');
      h.appendChild(el('p', { class: failed ? 'summary-fail' : 'summary-pass' },
        'Check: ' + data.check_summary));
    }
    const prov = Object.fromEntries(data.provenance || []);
    // when, which build, and the machine every wall time was measured on
    const bits = [['utc_time', ''], ['build_revision', 'revision '], ['host', 'host '],
      ['machine_cpu_model', 'CPU '], ['machine_cpus', 'CPUs ']].filter(([k]) => prov[k])
      .map(([k, label]) => label + prov[k]);
    if (bits.length) h.appendChild(el('p', {}, 'Run: ' + bits.join(', ')));

    const nav = document.getElementById('pb-nav');
    if (data.verdict) nav.appendChild(el('a', { href: '#table-verdict' }, 'Verdict'));
    for (const c of data.cases) nav.appendChild(el('a', { href: '#case-' + slug(c.name) }, c.name));
    if (hasWorkPrecision()) nav.appendChild(el('a', { href: '#work-precision' }, 'Work-precision'));
    if (hasCampaign()) nav.appendChild(el('a', { href: '#campaign' }, 'Campaign'));
    if (hasFriction()) nav.appendChild(el('a', { href: '#friction' }, 'Friction'));
    if (hasImpacts()) nav.appendChild(el('a', { href: '#impacts' }, 'Measured impacts'));
    if (hasValidity()) nav.appendChild(el('a', { href: '#validity' }, 'Physical validity'));
    if (hasScenes()) nav.appendChild(el('a', { href: '#scenes' }, 'Scenes'));
    for (const t of data.tables) nav.appendChild(el('a', { href: '#table-' + slug(t.id) }, t.title));
    if (data.results_file) nav.appendChild(el('a', { href: '#mapping' }, 'Parameter mapping'));
  }

  // ---- figures -------------------------------------------------------------
  const charts = [];

  function seriesLabel(s) {
    return s.engine === 'analytic' ? 'analytic (truth)' : s.engine;
  }

  // time ticks with as many decimals as their spacing needs: a zoom into a
  // 0.24 ms pulse reads 0.49650, 0.49655, ... not 0.496 four times
  function timeTicks(u, splits, axisIdx, space, incr) {
    const dec = Math.min(9, Math.max(0, Math.ceil(-Math.log10(incr) - 1e-9)));
    return splits.map((v) => (v === null || v === undefined ? '' : v.toFixed(dec)));
  }

  // the chart fills its column, down to a phone's width
  function chartWidth(container) {
    return Math.max(240, container.clientWidth || 900);
  }

  function makeChart(fig, container) {
    // the truth is drawn last, dashed black on top of the engines
    const order = fig.series.filter((s) => s.engine !== 'analytic')
      .concat(fig.series.filter((s) => s.engine === 'analytic'));
    const tables = order.map((s) => [data.grids[s.grid], s.y]);
    const aligned = tables.length ? uPlot.join(tables) : [[]];
    const series = [{
      label: 't, s',
      value: (u, v) => (v === null || v === undefined ? '-' : v.toPrecision(7)),
    }];
    for (const s of order) {
      const truth = s.engine === 'analytic';
      series.push({
        label: seriesLabel(s),
        stroke: s.colour,
        // the reference is drawn first and wider: where an engine's line
        // coincides with it, its edges stay visible
        width: s.engine === 'reference' ? 3.5 : 1.5,
        dash: truth ? [6, 4] : undefined,
        value: (u, v) => (v === null || v === undefined ? '-' : v.toPrecision(6)),
      });
    }
    // an off-scale series (an impulsive engine) does not set the default
    // value axis; the "fit all" button brings it in
    const clip = typeof fig.y_clip === 'number' ? fig.y_clip : null;
    const view = { fitAll: clip === null };
    const opts = {
      width: chartWidth(container),
      height: 320,
      scales: {
        x: { time: false },
        y: {
          range: (u, min, max) => {
            if (!view.fitAll && max > clip) max = clip;
            return uPlot.rangeNum(min, max, 0.1, true);
          },
        },
      },
      series: series,
      axes: [
        { label: 'time, s', values: timeTicks },
        { label: fig.y_label, size: 72 },
      ],
      cursor: { drag: { x: true, y: false } },
      legend: { live: true },
    };
    const u = new uPlot(opts, aligned, container);
    const xs = aligned[0];
    const fullRange = () => {
      if (xs.length) u.setScale('x', { min: xs[0], max: xs[xs.length - 1] });
    };
    return { u, fullRange, view, clip, order };
  }

  // The error panel under a figure: |series - yardstick| against time, log
  // scale, the yardstick (the truth, else the reference) linearly
  // interpolated at each series' own sample times. Its x range follows the
  // figure's zoom. Returns null when there is nothing to compare.
  function makeErrorChart(fig, container, mainU) {
    const base = fig.series.find((s) => s.engine === 'analytic') ||
      fig.series.find((s) => s.engine === 'reference');
    if (!base || fig.series.length < 2) return null;
    const bt = data.grids[base.grid];
    const by = base.y;
    const at = (t) => {
      if (!bt.length || t < bt[0] || t > bt[bt.length - 1]) return null;
      let lo = 0;
      let hi = bt.length - 1;
      while (hi - lo > 1) {
        const mid = (lo + hi) >> 1;
        if (bt[mid] <= t) lo = mid; else hi = mid;
      }
      const y0 = by[lo];
      const y1 = by[hi];
      if (y0 === null || y1 === null) return null;
      if (bt[hi] === bt[lo]) return y0;
      const w = (t - bt[lo]) / (bt[hi] - bt[lo]);
      return y0 + w * (y1 - y0);
    };
    const others = fig.series.filter((s) => s !== base);
    let any = false;
    const tables = others.map((s) => {
      const ts = data.grids[s.grid];
      const es = ts.map((t, i) => {
        const b = at(t);
        const y = s.y[i];
        if (b === null || y === null) return null;
        const d = Math.abs(y - b);
        if (!(d > 0) || !Number.isFinite(d)) return null;  // exact agreement: a gap on a log axis
        any = true;
        return Math.log10(d);
      });
      return [ts, es];
    });
    const label = base.engine === 'analytic' ? 'truth' : 'reference';
    if (!any) {
      container.appendChild(el('p', { class: 'note' }, 'Error panel: every series equals the ' + label + ' at every sample.'));
      return null;
    }
    const unit = (fig.y_label.split(', ')[1] || '');
    const aligned = uPlot.join(tables);
    // log10 of the error on a linear axis labelled in decades (uPlot's own
    // log axis lays out ticks over the whole range of every series: slow and
    // fragile over 20 decades)
    const u = new uPlot({
      width: chartWidth(container),
      height: 170,
      scales: {
        x: { time: false },
        y: { range: (uu, min, max) => [Math.floor(min), Math.max(Math.ceil(max), Math.floor(min) + 1)] },
      },
      series: [{ label: 't, s', value: (uu, v) => (v === null || v === undefined ? '-' : v.toPrecision(7)) }]
        .concat(others.map((s) => ({
          label: '|' + s.engine + ' - ' + label + '|',
          stroke: s.colour,
          width: s.engine === 'reference' ? 2.5 : 1.2,
          value: (uu, v) => (v === null || v === undefined ? '-' : Math.pow(10, v).toPrecision(3)),
        }))),
      axes: [{ label: 'time, s', values: timeTicks }, {
        label: '|error|' + (unit ? ', ' + unit : ''),
        size: 72,
        incrs: [1, 2, 3, 5, 10, 20],
        values: (uu, vals) => vals.map((v) => (Number.isInteger(v) ? '1e' + v : '')),
      }],
      cursor: { drag: { x: true, y: false } },
      legend: { live: true },
    }, aligned, container);
    container.appendChild(el('p', { class: 'hint' }, 'Error panel: |series - ' + label + '| on a log ' +
      'scale, the ' + label + ' interpolated at each series\u2019 samples. The page holds 7 significant ' +
      'digits per value, so an error below ~1e-7 of the value is a gap here (the metrics table has ' +
      'the full-precision errors).'));
    // the panel follows the figure's time range
    (mainU.hooks.setScale = mainU.hooks.setScale || []).push((mu, key) => {
      if (key === 'x') u.setScale('x', { min: mu.scales.x.min, max: mu.scales.x.max });
    });
    return { u, against: label, series: others.map((s, i) => {
      let points = 0;
      for (const v of aligned[i + 1] || []) if (typeof v === 'number' && Number.isFinite(v)) points++;
      return { engine: s.engine, points };
    }) };
  }

  function renderFigure(fig, parent) {
    const box = el('div', { class: 'figure', id: 'fig-' + fig.id });
    box.appendChild(el('h3', {}, fig.title));
    const controls = el('div', { class: 'controls' });
    const chartDiv = el('div', { class: 'chart' });
    box.appendChild(controls);
    box.appendChild(chartDiv);
    const notes = fig.series.filter((s) => s.note).map((s) => seriesLabel(s) + ': ' + s.note);
    const counts = fig.series.map((s) => seriesLabel(s) + ' ' + s.shown_points + ' of ' +
      s.full_points + ' samples');
    box.appendChild(el('p', { class: 'series-notes' }, counts.join('; ') +
      (notes.length ? '. ' + notes.join('; ') : '')));
    parent.appendChild(box);

    if (!fig.series.length) {
      chartDiv.appendChild(el('p', { class: 'note' }, 'No run of this case is ok: nothing to plot.'));
      charts.push({ id: fig.id, title: fig.title, series: [] });
      return;
    }
    const { u, fullRange, view, clip, order } = makeChart(fig, chartDiv);
    // redraws of the figure, counted: the browser test waits for the next
    // one after a zoom, not for a fixed time
    box.dataset.draws = '0';
    (u.hooks.draw = u.hooks.draw || []).push(() => {
      box.dataset.draws = String(Number(box.dataset.draws) + 1);
    });
    const errorDiv = el('div', { class: 'chart error-panel' });
    box.insertBefore(errorDiv, chartDiv.nextSibling);
    const errorChart = makeErrorChart(fig, errorDiv, u);
    controls.appendChild(el('button', { type: 'button', onclick: fullRange }, 'reset zoom'));
    if (clip !== null) {
      const off = fig.series.filter((s) => s.off_scale).map((s) => s.engine).join(', ');
      const toggle = el('button', { type: 'button', title: off + ' peak far above the others' }, 'fit all (' + off + ')');
      toggle.addEventListener('click', () => {
        view.fitAll = !view.fitAll;
        toggle.textContent = view.fitAll ? 'fit the others' : 'fit all (' + off + ')';
        u.setScale('x', { min: u.scales.x.min, max: u.scales.x.max });
      });
      controls.appendChild(toggle);
    }
    for (const ep of fig.episodes) {
      controls.appendChild(el('button', {
        type: 'button',
        title: 't = ' + ep.t0 + ' to ' + ep.t1 + ' s',
        onclick: () => u.setScale('x', { min: ep.t0, max: ep.t1 }),
      }, 'zoom to ' + ep.label));
    }
    const entry = {
      id: fig.id,
      title: fig.title,
      paperFigure: fig.paper_figure,
      uplot: u,
      errorUplot: errorChart ? errorChart.u : null,
      errorPanel: errorChart ? { against: errorChart.against, series: errorChart.series } : null,
      series: [],
    };
    const xs = u.data[0] || [];
    order.forEach((s, i) => {
      const ys = u.data[i + 1] || [];
      let points = 0;
      let tLast = null;
      let peak = null;
      ys.forEach((v, k) => {
        if (typeof v === 'number' && Number.isFinite(v)) {
          points++;
          tLast = xs[k];
          if (peak === null || v > peak) peak = v;
        }
      });
      entry.series.push({ engine: s.engine, points: points, tLast: tLast, peak: peak });
    });
    charts.push(entry);
  }

  function renderCases(main) {
    // how the figures are drawn: once, before the first case
    if (data.results_file && data.cases.length) {
      main.appendChild(el('p', { class: 'note' }, data.downsampling +
        ' Drag across a plot to zoom in time, double-click to zoom out; click a legend entry to hide or show its series.'));
    }
    for (const c of data.cases) {
      const sec = el('section', { id: 'case-' + slug(c.name) });
      sec.appendChild(el('h2', {}, c.name));
      sec.appendChild(el('p', {}, c.description));
      sec.appendChild(el('p', { class: 'case-meta' },
        (c.paper ? 'Paper: ' + c.paper + '. ' : '') + 'Truth: ' + c.truth + '.' +
        (c.overrides.length ? ' Overrides: ' + c.overrides.map((o) => o[0] + '=' + o[1]).join(', ') : '')));
      if (c.assumptions.length) {
        const d = el('details', { class: 'assumptions' }, el('summary', {}, 'Assumptions (' +
          c.assumptions.length + ')'));
        d.appendChild(el('ul', {}, ...c.assumptions.map((a) => el('li', {}, a))));
        sec.appendChild(d);
      }
      main.appendChild(sec);
      for (const f of c.figures) renderFigure(f, sec);
    }
  }

  // ---- tables --------------------------------------------------------------
  function renderTable(t, main, heading) {
    const sec = el('section', { id: 'table-' + slug(t.id) });
    sec.appendChild(el(heading || 'h2', {}, t.title));
    if (t.note) sec.appendChild(el('p', { class: 'note' }, t.note));
    if (!t.rows.length) {
      sec.appendChild(el('p', {}, '(none)'));
      main.appendChild(sec);
      return;
    }
    const table = el('table', { class: 'pb', id: 'tbl-' + t.id });
    const body = el('tbody');
    // click a header to sort by it (numbers as numbers), again to reverse
    let sortedBy = -1;
    let ascending = true;
    const sortBy = (j) => {
      ascending = sortedBy === j ? !ascending : true;
      sortedBy = j;
      const key = (r) => r.cells[j];
      const sorted = [...rows].sort((a, b) => {
        const x = key(a);
        const y = key(b);
        const nx = x === '' ? NaN : Number(x);
        const ny = y === '' ? NaN : Number(y);
        let c;
        if (!Number.isNaN(nx) && !Number.isNaN(ny)) c = nx - ny;
        else if (!Number.isNaN(nx) !== !Number.isNaN(ny)) c = Number.isNaN(nx) ? 1 : -1;
        else c = x.localeCompare(y);
        return ascending ? c : -c;
      });
      for (const r of sorted) body.appendChild(r.tr);
      headers.forEach((h, k) => h.setAttribute('aria-sort', k === j ? (ascending ? 'ascending' : 'descending') : 'none'));
    };
    const headers = t.columns.map((c, j) => el('th', { class: 'sortable', title: 'sort by ' + c, onclick: () => sortBy(j) }, c));
    table.appendChild(el('thead', {}, el('tr', {}, ...headers)));
    const rows = t.rows.map((r, i) => {
      const tr = el('tr', { class: t.row_status[i] || '' });
      r.forEach((cell, j) => {
        const td = el('td', {}, cell);
        // capability cells coloured by status (ok, diverged, unsupported)
        if (t.id === 'capability' && j > 0) td.className = 'st-' + cell.split(/[ :]/)[0];
        tr.appendChild(td);
      });
      body.appendChild(tr);
      // the metrics beyond the gated checks and the truth comparisons start folded
      const folded = t.id === 'metrics' && !t.row_status[i] && r[2] !== 'truth';
      return { tr, cells: r, text: r.join(' ').toLowerCase(), status: t.row_status[i], folded };
    });
    table.appendChild(body);

    // a filter for long tables: every word must occur in the row
    if (t.rows.length > 15) {
      const input = el('input', { type: 'text', placeholder: 'filter rows, e.g. falling_ball mujoco peak_force' });
      const hasFail = t.row_status.includes('fail');
      const onlyFail = el('input', { type: 'checkbox' });
      const count = el('span', { class: 'note' });
      const anyFolded = rows.some((r) => r.folded);
      const showAll = el('input', { type: 'checkbox' });
      const apply = () => {
        const words = input.value.toLowerCase().split(/\s+/).filter(Boolean);
        let shown = 0;
        for (const r of rows) {
          const ok = words.every((w) => r.text.includes(w)) && (!onlyFail.checked || r.status === 'fail') &&
            (showAll.checked || !r.folded);
          r.tr.style.display = ok ? '' : 'none';
          shown += ok ? 1 : 0;
        }
        count.textContent = ' ' + shown + ' of ' + rows.length + ' rows';
      };
      input.addEventListener('input', apply);
      onlyFail.addEventListener('change', apply);
      showAll.addEventListener('change', apply);
      const filter = el('div', { class: 'filter' }, 'Filter: ', input);
      if (hasFail) filter.appendChild(el('label', {}, ' ', onlyFail, ' failed only'));
      if (anyFolded) {
        filter.appendChild(el('label', {}, ' ', showAll, ' every metric (' +
          rows.filter((r) => r.folded).length + ' more: against the reference, between engines, self)'));
      }
      filter.appendChild(count);
      sec.appendChild(filter);
      apply();
    }
    sec.appendChild(el('div', { class: 'table-wrap' }, table));
    main.appendChild(sec);
  }

  // ---- work-precision (planarbench sweep) -----------------------------------
  function hasWorkPrecision() {
    return Boolean(data.work_precision && data.work_precision.cases.length);
  }

  // The plots are SVG documents the report wrote itself (report_work_precision_svg.cpp,
  // every text XML-escaped, no scripts): parsed as XML, never as HTML.
  function svgNode(text) {
    const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
    if (doc.getElementsByTagName('parsererror').length) return el('p', { class: 'note' }, 'plot unreadable');
    return document.importNode(doc.documentElement, true);
  }

  function renderWorkPrecision(main) {
    if (!hasWorkPrecision()) return;
    const wp = data.work_precision;
    const sec = el('section', { id: 'work-precision' });
    sec.appendChild(el('h2', {}, 'Work-precision'));
    sec.appendChild(el('p', { class: 'note' }, wp.note));
    for (const c of wp.cases) {
      const box = el('div', { class: 'wp-case', id: 'wp-' + slug(c.name) });
      box.appendChild(el('h3', {}, c.name));
      box.appendChild(el('p', { class: 'case-meta' }, 'Truth: ' + c.truth +
        (c.truth_note ? ' (' + c.truth_note + ')' : '') + '.'));
      box.appendChild(el('div', { class: 'wp-plot' }, svgNode(c.svg)));
      renderTable(c.summary, box, 'h4');
      if (c.not_plotted.length) {
        box.appendChild(el('details', {}, el('summary', {}, 'Not plotted (' + c.not_plotted.length + ')'),
          el('ul', {}, ...c.not_plotted.map((n) => el('li', {}, n)))));
      }
      const rungs = el('details', {}, el('summary', {}, 'Every rung (' + c.rungs.rows.length + ')'));
      renderTable(c.rungs, rungs, 'h4');
      box.appendChild(rungs);
      sec.appendChild(box);
    }
    if (wp.provenance.rows.length) renderTable(wp.provenance, sec, 'h3');
    main.appendChild(sec);
  }

  // ---- campaign (planarbench campaign) --------------------------------------
  function hasCampaign() {
    return Boolean(data.campaign && data.campaign.cases.length);
  }

  function renderCampaign(main) {
    if (!hasCampaign()) return;
    const cp = data.campaign;
    const sec = el('section', { id: 'campaign' });
    sec.appendChild(el('h2', {}, 'Campaign'));
    sec.appendChild(el('p', { class: 'note' }, cp.note));
    for (const c of cp.cases) {
      const box = el('div', { class: 'wp-case', id: 'campaign-' + slug(c.name) });
      box.appendChild(el('h3', {}, c.name));
      box.appendChild(el('p', { class: 'case-meta' }, 'Truth of position_error_m: ' + c.truth + '.'));
      for (const f of c.figures) box.appendChild(el('div', { class: 'wp-plot' }, svgNode(f.svg)));
      for (const t of c.tables) renderTable(t, box, 'h4');
      sec.appendChild(box);
    }
    main.appendChild(sec);
  }

  // a section's figures (SVG text), each in a box with the id prefix + its id
  function appendFigures(sec, figures, prefix) {
    for (const f of figures) {
      sec.appendChild(el('div', { class: 'wp-plot', id: prefix + slug(f.id) }, svgNode(f.svg)));
    }
  }

  // ---- friction (SPEC §7) ----------------------------------------------------
  function hasFriction() {
    return Boolean(data.friction && data.friction.figures.length);
  }

  function renderFriction(main) {
    if (!hasFriction()) return;
    const fr = data.friction;
    const sec = el('section', { id: 'friction' });
    sec.appendChild(el('h2', {}, 'Friction'));
    sec.appendChild(el('p', { class: 'note' }, fr.note));
    appendFigures(sec, fr.figures, 'friction-');
    if (fr.curve && fr.curve.rows.length) renderTable(fr.curve, sec, 'h3');
    if (fr.family && fr.family.rows.length) renderTable(fr.family, sec, 'h3');
    main.appendChild(sec);
  }

  // ---- measured impacts (SPEC §8) ------------------------------------------
  function hasImpacts() {
    return Boolean(data.impacts && data.impacts.file);
  }

  function renderImpacts(main) {
    if (!hasImpacts()) return;
    const im = data.impacts;
    const sec = el('section', { id: 'impacts' });
    sec.appendChild(el('h2', {}, 'Measured impacts'));
    sec.appendChild(el('p', { class: 'note' }, im.note));
    for (const t of im.tables) renderTable(t, sec, 'h3');
    appendFigures(sec, im.figures, 'impacts-');
    main.appendChild(sec);
  }

  // ---- physical validity (SPEC §9) -----------------------------------------
  function hasValidity() {
    return Boolean(data.validity && data.validity.table && data.validity.table.rows.length);
  }

  function renderValidity(main) {
    if (!hasValidity()) return;
    const v = data.validity;
    const sec = el('section', { id: 'validity' });
    sec.appendChild(el('h2', {}, 'Physical validity'));
    sec.appendChild(el('p', { class: 'note' }, v.note));
    const ul = el('ul', { class: 'readings' });
    for (const line of v.readings) ul.appendChild(el('li', {}, line));
    sec.appendChild(ul);
    renderTable(v.table, sec, 'h3');
    appendFigures(sec, v.figures, 'validity-');
    main.appendChild(sec);
  }

  // ---- scenes (SPEC §11) ---------------------------------------------------
  function hasScenes() {
    return Boolean(data.scenes && data.scenes.tables && data.scenes.tables.length);
  }

  function renderScenes(main) {
    if (!hasScenes()) return;
    const sc = data.scenes;
    const sec = el('section', { id: 'scenes' });
    sec.appendChild(el('h2', {}, 'Scenes'));
    sec.appendChild(el('p', { class: 'note' }, sc.note));
    for (const t of sc.tables) renderTable(t, sec, 'h3');
    appendFigures(sec, sc.figures, 'scenes-');
    main.appendChild(sec);
  }

  // ---- parameter mapping ---------------------------------------------------
  function jsonNode(v) {
    if (v === null || typeof v !== 'object') return document.createTextNode(String(v));
    if (Array.isArray(v) && v.every((x) => x === null || typeof x !== 'object')) {
      return document.createTextNode('[' + v.map(String).join(', ') + ']');
    }
    const dl = el('dl');
    const entries = Array.isArray(v) ? v.map((x, i) => [String(i), x]) : Object.entries(v);
    for (const [k, x] of entries) {
      dl.appendChild(el('dt', {}, k));
      dl.appendChild(el('dd', {}, jsonNode(x)));
    }
    return dl;
  }

  function renderMappings(main) {
    const sec = el('section', { id: 'mapping', class: 'mapping' });
    sec.appendChild(el('h2', {}, 'Parameter mapping'));
    sec.appendChild(el('p', { class: 'note' }, 'How each engine expressed each case\'s contact ' +
      'law (its mapping attribute in the results file), and what it could not express.'));
    for (const m of data.mappings) {
      sec.appendChild(el('h3', {}, m.case + ' / ' + m.engine + ' (' + m.status + ')'));
      if (m.not_expressed.length) {
        sec.appendChild(el('div', { class: 'lost' }, el('strong', {}, 'Could not express:'),
          el('ul', {}, ...m.not_expressed.map((n) => el('li', {}, n)))));
      } else {
        sec.appendChild(el('p', { class: 'note' }, 'Could not express: nothing recorded.'));
      }
      if (m.mapping && Object.keys(m.mapping).length) {
        sec.appendChild(el('details', {}, el('summary', {}, 'full mapping'), jsonNode(m.mapping)));
      }
    }
    main.appendChild(sec);
  }

  // ---- page ----------------------------------------------------------------
  renderHeader();
  const main = document.getElementById('pb-main');
  main.removeChild(document.getElementById('pb-loading'));
  // the answer first: which engine, how wrong, at what cost
  if (data.verdict) renderTable(data.verdict, main);
  renderCases(main);
  renderWorkPrecision(main);
  renderCampaign(main);
  renderFriction(main);
  renderImpacts(main);
  renderValidity(main);
  renderScenes(main);
  for (const t of data.tables) renderTable(t, main);
  if (data.results_file) renderMappings(main);

  // the charts follow the window's width 150 ms after its last resize; each
  // such redraw is counted on <html data-resizes>: the browser test waits on
  // the count, not on a fixed time
  let resizeTimer = null;
  let resizes = 0;
  document.documentElement.dataset.resizes = '0';
  window.addEventListener('resize', () => {
    clearTimeout(resizeTimer);
    resizeTimer = setTimeout(() => {
      for (const c of charts) {
        if (c.uplot) c.uplot.setSize({ width: chartWidth(c.uplot.root.parentNode), height: 320 });
        if (c.errorUplot) c.errorUplot.setSize({ width: chartWidth(c.errorUplot.root.parentNode), height: 170 });
      }
      document.documentElement.dataset.resizes = String(++resizes);
    }, 150);
  });

  // published once the browser has painted the charts
  requestAnimationFrame(() => {
    window.planarbenchReport = {
      charts: charts.map((c) => ({
        id: c.id, title: c.title, paperFigure: c.paperFigure, series: c.series, errorPanel: c.errorPanel,
      })),
    };
  });
})();
