// planarbench report page: renders the embedded report data (JSON in
// #pb-data) into figures (uPlot) and tables. Every text goes in through
// textContent, never as HTML. When the charts are drawn it publishes
// window.planarbenchReport = { charts: [{ id, title, series: [{ engine, points }] }] }
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
    if (data.results_file) h.appendChild(el('p', {}, 'Results file: ', el('code', {}, data.results_file)));
    if (data.sweep_file) h.appendChild(el('p', {}, 'Sweep file: ', el('code', {}, data.sweep_file)));
    if (data.thresholds_file) {
      h.appendChild(el('p', {}, 'Thresholds: ', el('code', {}, data.thresholds_file)));
    }
    if (data.check_summary) {
      const failed = !/, 0 failed$/.test(data.check_summary);
      h.appendChild(el('p', { class: failed ? 'summary-fail' : 'summary-pass' },
        'Check: ' + data.check_summary));
    }
    const prov = Object.fromEntries(data.provenance || []);
    const bits = ['utc_time', 'build_revision', 'host'].filter((k) => prov[k])
      .map((k) => k + ' ' + prov[k]);
    if (bits.length) h.appendChild(el('p', {}, 'Run: ' + bits.join(', ')));
    if (data.results_file) {
      h.appendChild(el('p', { class: 'note' }, data.downsampling +
        ' Drag across a plot to zoom in time, double-click to zoom out; click a legend entry to hide or show its series.'));
    }

    const nav = document.getElementById('pb-nav');
    for (const c of data.cases) nav.appendChild(el('a', { href: '#case-' + slug(c.name) }, c.name));
    if (hasWorkPrecision()) nav.appendChild(el('a', { href: '#work-precision' }, 'Work-precision'));
    for (const t of data.tables) nav.appendChild(el('a', { href: '#table-' + slug(t.id) }, t.title));
    if (data.results_file) nav.appendChild(el('a', { href: '#mapping' }, 'Parameter mapping'));
  }

  // ---- figures -------------------------------------------------------------
  const charts = [];

  function seriesLabel(s) {
    return s.engine === 'analytic' ? 'analytic (truth)' : s.engine;
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
        width: 1.5,
        dash: truth ? [6, 4] : undefined,
        value: (u, v) => (v === null || v === undefined ? '-' : v.toPrecision(6)),
      });
    }
    // an off-scale series (an impulsive engine) does not set the default
    // value axis; the "fit all" button brings it in
    const clip = typeof fig.y_clip === 'number' ? fig.y_clip : null;
    const view = { fitAll: clip === null };
    const opts = {
      width: Math.max(400, container.clientWidth || 900),
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
        { label: 'time, s' },
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
    const entry = { id: fig.id, title: fig.title, uplot: u, series: [] };
    order.forEach((s, i) => {
      const ys = u.data[i + 1] || [];
      let points = 0;
      for (const v of ys) if (typeof v === 'number' && Number.isFinite(v)) points++;
      entry.series.push({ engine: s.engine, points: points });
    });
    charts.push(entry);
  }

  function renderCases(main) {
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
    table.appendChild(el('thead', {}, el('tr', {}, ...t.columns.map((c) => el('th', {}, c)))));
    const body = el('tbody');
    const rows = t.rows.map((r, i) => {
      const tr = el('tr', { class: t.row_status[i] || '' });
      r.forEach((cell, j) => {
        const td = el('td', {}, cell);
        // capability cells coloured by status (ok, diverged, unsupported)
        if (t.id === 'capability' && j > 0) td.className = 'st-' + cell.split(/[ :]/)[0];
        tr.appendChild(td);
      });
      body.appendChild(tr);
      return { tr, text: r.join(' ').toLowerCase(), status: t.row_status[i] };
    });
    table.appendChild(body);

    // a filter for long tables: every word must occur in the row
    if (t.rows.length > 15) {
      const input = el('input', { type: 'text', placeholder: 'filter rows, e.g. falling_ball mujoco peak_force' });
      const hasFail = t.row_status.includes('fail');
      const onlyFail = el('input', { type: 'checkbox' });
      const count = el('span', { class: 'note' });
      const apply = () => {
        const words = input.value.toLowerCase().split(/\s+/).filter(Boolean);
        let shown = 0;
        for (const r of rows) {
          const ok = words.every((w) => r.text.includes(w)) && (!onlyFail.checked || r.status === 'fail');
          r.tr.style.display = ok ? '' : 'none';
          shown += ok ? 1 : 0;
        }
        count.textContent = ' ' + shown + ' of ' + rows.length + ' rows';
      };
      input.addEventListener('input', apply);
      onlyFail.addEventListener('change', apply);
      const filter = el('div', { class: 'filter' }, 'Filter: ', input);
      if (hasFail) filter.appendChild(el('label', {}, ' ', onlyFail, ' failed only'));
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
  renderCases(main);
  renderWorkPrecision(main);
  for (const t of data.tables) renderTable(t, main);
  if (data.results_file) renderMappings(main);

  let resizeTimer = null;
  window.addEventListener('resize', () => {
    clearTimeout(resizeTimer);
    resizeTimer = setTimeout(() => {
      for (const c of charts) {
        if (c.uplot) c.uplot.setSize({ width: Math.max(400, c.uplot.root.parentNode.clientWidth), height: 320 });
      }
    }, 150);
  });

  // published once the browser has painted the charts
  requestAnimationFrame(() => {
    window.planarbenchReport = {
      charts: charts.map((c) => ({ id: c.id, title: c.title, series: c.series })),
    };
  });
})();
