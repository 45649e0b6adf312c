// The workbench of `ncurve serve` in a real browser: headless Chromium (Debian's), playwright-core.
//   node workbench.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Starts `ncurve serve --port 0 examples/spiral.nc`, opens the page and checks: the moves drawn
// against the run's count, an error typed in the editor marked at its line, stepping the debugger
// forward and back with #104 changing, a watchpoint on #104 stopped on (variables the control has
// not refused), a move clicked landing on its line; the machine that of `ncurve run` without
// --machine; at 1000 x 700 the axes readable in every view; Measure on a program of hand-known
// points (ends, an arc's radius and centre, the view's plane, iso) at 1024 x 768 and 1920 x 1080;
// axis numbers zoomed in and out, no number or axis name over another (one rapid zoomed out in the
// Iso view too); the holes of a G81 pattern; an empty editor calm. Screenshots go to
// OUT_DIR. Exit 77 (skipped) where no Chromium is installed.
'use strict';
const {execFileSync} = require('child_process');
const fs = require('fs');
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

const spiral = path.join(src, 'examples/spiral.nc');
const summary = JSON.parse(execFileSync(ncurve, ['run', spiral, '--json'], {encoding: 'utf8'}));

(async () => {
  const {server, port} = await serve(ncurve, [spiral]);
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  await finish({check, counts, out}, async () => {
    const {page, errors} = await newPage(context);
    const offsite = [];
    page.on('request', (r) => { if (!r.url().startsWith(`http://127.0.0.1:${port}/`)) offsite.push(r.url()); });
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1);
    const W = () => page.evaluate(() => ({runs: ncurveWorkbench.runs, moveCount: ncurveWorkbench.moveCount,
      diagnostics: ncurveWorkbench.diagnostics, pos: ncurveWorkbench.pos, vars: ncurveWorkbench.vars,
      state: ncurveWorkbench.plot.state(), text: ncurveWorkbench.editor.text, cursor: ncurveWorkbench.editor.cursorLine(),
      highlighted: ncurveWorkbench.highlighted, stopped: ncurveWorkbench.stoppedOnBreak, drawnUpTo: ncurveWorkbench.drawnUpTo}));
    let w = await W();
    check(w.text === fs.readFileSync(spiral, 'utf8'), 'the FILE given to serve is in the editor');
    // no serve --machine: the page shows and runs on what `ncurve run` without --machine runs on
    const machine = await page.evaluate(() => ({value: document.getElementById('machine').value,
      text: document.getElementById('machine').selectedOptions[0].text, ran: ncurveWorkbench.summary.machine}));
    check(machine.value === '' && /factory parameters \(ncurve run's default\)/.test(machine.text) && machine.ran === summary.machine,
          `the machine shown is ncurve run's default: "${machine.text}", ran on "${machine.ran}" (run: "${summary.machine}")`);
    check(w.moveCount === summary.motions && w.state.moveCount === summary.motions,
          `${w.moveCount} moves drawn, the run made ${summary.motions}`);
    check(w.state.kinds.feed === summary.moves.line && w.state.kinds.rapid === summary.moves.rapid, `moves by kind ${JSON.stringify(w.state.kinds)}`);
    check(errors.length === 0, `no script errors (${errors.join('; ')})`);
    check(offsite.length === 0, `nothing loaded from elsewhere (${offsite.join(' ')})`);
    check(await page.evaluate(() => document.querySelectorAll('.wb-hl .g').length > 5 && document.querySelectorAll('.wb-hl .k').length >= 3 &&
          document.querySelectorAll('.wb-hl .c').length >= 6 && document.querySelectorAll('.wb-hl .v').length > 10), 'syntax highlighted');
    await page.screenshot({path: path.join(out, 'workbench-spiral.png')});

    // click a lonely move: the editor lands on its line
    const target = await page.evaluate(() => {
      const B = ncurveWorkbench.plot, n = B.moves.count, pts = [];
      for (let i = 0; i < n; i++) pts.push(B.screenOf(i));
      const r = B.renderer.domElement.getBoundingClientRect();
      for (let k = 0; k < n; k++) {
        const i = (Math.floor(n / 2) + k) % n, p = pts[i];
        if (p.x < r.left + 60 || p.y < r.top + 60 || p.x > r.right - 60 || p.y > r.bottom - 60) continue;
        if (pts.every((q, j) => j === i || Math.hypot(q.x - p.x, q.y - p.y) > 6)) return {i, p, line: B.moves.line[i]};
      }
      return null;
    });
    check(target !== null, 'a move to click');
    if (target) {
      await page.mouse.click(target.p.x, target.p.y);
      await page.waitForTimeout(200);
      w = await W();
      check(w.cursor === target.line && target.line === 23, `clicking move ${target.i} selects its line ${target.line} (cursor on ${w.cursor})`);
      check(w.highlighted.length === summary.moves.line - 1, `its line's ${w.highlighted.length} moves highlighted`);
      await page.screenshot({path: path.join(out, 'workbench-click.png')});
    }

    // the debugger: step forward and back over the loop, #104 changes
    await page.click('button[data-tab="debug"]');
    const line20 = await page.evaluate(() => {  // the first block on line 20 (#104=...)
      const t = ncurveWorkbench.trace;
      for (let k = 0; k < t.count; k++) if (t.at(k).line === 20) return k;
      return -1;
    });
    check(line20 > 0, `line 20 executed (block ${line20 + 1})`);
    await page.evaluate((k) => ncurveWorkbench.goTo(k), line20);
    w = await W();
    check(w.vars['#104'] === undefined, `before line 20 first runs, #104 is vacant (${w.vars['#104']})`);
    await page.click('#dbg-fwd');
    w = await W();
    const r1 = 1 + 2 * 3.6 * 3.1415927 / 180;
    check(Math.abs(w.vars['#104'] - r1) < 1e-6, `one step on, #104 = ${w.vars['#104']} (1 + 2*3.6*pi/180 = ${r1.toFixed(6)})`);
    check(await page.evaluate(() => !!document.querySelector('.wb-vars tr.changed')), 'the changed variable is highlighted');
    check(await page.evaluate(() => document.querySelector('.wb-band.current') !== null), 'the current line is highlighted');
    await page.click('#dbg-back');
    w = await W();
    check(w.vars['#104'] === undefined && w.pos === line20, 'one step back, #104 vacant again');
    // a watchpoint on #104 from the start: stops right after its first write, then at the second
    await page.click('#dbg-first');
    // variables the control has not are refused, and why beside the box
    for (const [bad, why] of [['#99999', /PS0115 #99999 is not a variable of this control/], ['#0', /#0 is always vacant/],
      ['#abc', /"#abc" is not a variable/], ['#1.5', /not a variable/]]) {
      await page.fill('#watch-var', bad);
      await page.click('#watch-add');
      await page.waitForFunction(() => document.getElementById('watch-why').textContent !== '');
      const said = await page.evaluate(() => ({why: document.getElementById('watch-why').textContent,
        chips: document.querySelectorAll('#watches .w').length}));
      check(why.test(said.why) && said.chips === 0, `watch ${bad} refused: ${said.why}`);
      await page.evaluate(() => { document.getElementById('watch-why').textContent = ''; });
    }
    await page.fill('#watch-var', '#104');
    await page.click('#watch-add');
    await page.waitForSelector('#watches .w');
    check(await page.evaluate(() => document.getElementById('watch-why').textContent === ''), 'watch #104 taken');
    await page.click('#dbg-next-break');
    w = await W();
    check(w.stopped && w.pos === line20 + 1 && Math.abs(w.vars['#104'] - r1) < 1e-6, `the watchpoint stops after the write of #104 (block ${w.pos + 1})`);
    await page.click('#dbg-next-break');
    w = await W();
    const r2 = 1 + 2 * 7.2 * 3.1415927 / 180;
    check(w.stopped && Math.abs(w.vars['#104'] - r2) < 1e-6, `and again at the next (#104 = ${w.vars['#104']})`);
    check(w.drawnUpTo > 0 && w.drawnUpTo < summary.motions, `the path drawn up to the tool (${w.drawnUpTo} of ${summary.motions})`);
    await page.screenshot({path: path.join(out, 'workbench-debugger.png')});
    await page.click('#dbg-prev-break');
    w = await W();
    check(w.pos === line20 + 1, 'back to the previous watchpoint stop');
    // a breakpoint on line 22 by clicking the gutter
    await page.evaluate(() => document.querySelectorAll('#watches .w').forEach((e) => e.click()));
    const g = await page.evaluate(() => ncurveWorkbench.editor.gutterOf(22));
    await page.mouse.click(g.x, g.y);
    await page.click('#dbg-first');
    await page.click('#dbg-next-break');
    w = await W();
    const line = await page.evaluate(() => ncurveWorkbench.state.line);
    check(w.stopped && line === 22, `the line breakpoint stops on line 22 (${line})`);

    // type an error: its mark at the right line after the re-run
    await page.click('button[data-tab="summary"]');
    const runs = w.runs;
    await page.evaluate(() => { window.firstCanvas = ncurveWorkbench.plot.renderer.domElement; });
    const at = await page.evaluate(() => ncurveWorkbench.editor.screenOf(20, 40));
    await page.mouse.click(at.x, at.y);
    await page.keyboard.press('End');
    await page.keyboard.type(' #1=[1+');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), runs);
    w = await W();
    check(await page.evaluate(() => ncurveWorkbench.plot.renderer.domElement === firstCanvas &&
          document.querySelectorAll('#plot canvas').length === 1), 'the re-run drew with the same WebGL canvas');
    const alarm = w.diagnostics.find((d) => d.severity === 'error');
    check(alarm && alarm.line === 20, `the alarm marks line 20 (${alarm && `${alarm.code} line ${alarm.line}: ${alarm.message}`})`);
    const mark = await page.evaluate(() => {
      const m = document.querySelector('.wb-mark.error');
      return m && {line: +m.dataset.line, top: m.getBoundingClientRect().top};
    });
    const lineTop = await page.evaluate(() => ncurveWorkbench.editor.screenOf(20, 1).y);
    check(mark && mark.line === 20 && Math.abs(mark.top - lineTop) < 12, 'its wavy mark is drawn on line 20');
    const m = await page.evaluate(() => { const r = document.querySelector('.wb-mark.error').getBoundingClientRect(); return {x: r.left + 3, y: r.top - 4}; });
    await page.mouse.move(m.x, m.y);
    await page.waitForTimeout(100);
    const tip = await page.evaluate(() => { const t = document.querySelector('.wb-tip'); return t.hidden ? '' : t.textContent; });
    check(alarm && tip.includes(alarm.code), `hovering it shows the code and message (${tip})`);
    await page.screenshot({path: path.join(out, 'workbench-alarm.png')});
    // at 1000 x 700, in every view of the spiral and of a wide program of little depth: the tick
    // marks along each axis at least 8 px apart on the screen, the numbers 48 px, and each axis
    // name shown whole on the canvas, clear of the buttons and the legend
    await page.setViewportSize({width: 1000, height: 700});
    await page.waitForTimeout(200);
    // the numbers and axis names shown whose boxes on the page overlap another's, in pairs
    const labelsOverlapping = () => page.evaluate(() => {
      const rs = [...document.querySelectorAll('#plot .ncurve-label.tick, #plot .ncurve-label.axis-name')]
        .filter((e) => e.style.display !== 'none' && e.offsetWidth).map((e) => ({t: e.textContent, r: e.getBoundingClientRect()}));
      const bad = [];
      for (let i = 0; i < rs.length; i++) for (let j = i + 1; j < rs.length; j++) {
        const a = rs[i].r, b = rs[j].r;
        if (a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom) bad.push(`${rs[i].t} / ${rs[j].t}`);
      }
      return bad;
    });
    const axesLook = async (what) => {
      for (const view of await page.evaluate(() => ncurveWorkbench.plot.views)) {
        const a = await page.evaluate((v) => {
          const B = ncurveWorkbench.plot;
          B.setView(v);
          B.render();  // the labels placed now, not at the next frame
          const c = B.renderer.domElement.getBoundingClientRect(), box = (q) => {
            const r = document.querySelector(q).getBoundingClientRect();
            return {l: r.left - c.left, t: r.top - c.top, r: r.right - c.left, b: r.bottom - c.top};
          };
          const p = document.getElementById('plot').getBoundingClientRect();
          return {axes: B.state().axes, W: c.width, H: c.height, boxes: ['#views', '#legend', '.wb-colour'].map(box),
            fits: Math.abs(c.width - p.width) < 1 && Math.abs(c.height - p.height) < 1};
        }, view);
        const gap = (pts) => Math.min(Infinity, ...pts.slice(1).map((p, i) => Math.hypot(p[0] - pts[i][0], p[1] - pts[i][1])));
        const marks = Math.min(...a.axes.marks.map(gap)), numbers = Math.min(...a.axes.numbers.map(gap));
        const bad = a.axes.names.filter((n) => n.x - n.w / 2 < 0 || n.x + n.w / 2 > a.W || n.y - n.h / 2 < 0 || n.y + n.h / 2 > a.H ||
          a.boxes.some((b) => n.x + n.w / 2 > b.l && n.x - n.w / 2 < b.r && n.y + n.h / 2 > b.t && n.y - n.h / 2 < b.b));
        check(a.fits && marks >= 8 && numbers >= 48 && a.axes.names.length >= 2 && bad.length === 0,
              `${what}, ${view}: marks ${marks.toFixed(0)} px apart, numbers ${numbers.toFixed(0)} px, names ${a.axes.names.map((n) => n.text).join(' · ')}` +
              (bad.length ? `; cut or covered: ${JSON.stringify(bad)} (canvas ${a.W} x ${a.H}, boxes ${JSON.stringify(a.boxes)})` : ''));
        const overlapping = await labelsOverlapping();
        check(overlapping.length === 0, `${what}, ${view}: no number or axis name over another (${overlapping.join(', ')})`);
      }
    };
    let before = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('.wb-input', fs.readFileSync(spiral, 'utf8'));
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
    await axesLook('the spiral');
    await page.evaluate(() => ncurveWorkbench.plot.setView('iso'));
    await page.screenshot({path: path.join(out, 'workbench-axes-1000.png')});
    before = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('.wb-input', 'G00 X0 Y0 Z2.\nG01 Z-0.5 F300.\nX100. Y60.\nG00 Z2.\nM30\n');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
    await axesLook('100 x 60 x 2.5 mm');
    await page.evaluate(() => ncurveWorkbench.plot.setView('iso'));
    await page.screenshot({path: path.join(out, 'workbench-axes-flat.png')});
    // Measure, on a program of hand-known points: the line X0 Y0 -> X30 Y40 is 50 long (30, 40, 0);
    // the arc G2 X50 Y60 R20 from X30 Y40 has its centre at X50 Y40 and its middle at 135 degrees,
    // X50-20cos45 Y40+20sin45, 2*20*sin(22.5) = 15.307 from its end
    before = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('.wb-input', 'G17 G90 G21 G0 X0 Y0 Z5.\nG1 Z-1. F100.\nG1 X30. Y0\nN40 G1 X30. Y40.\nG2 X50. Y60. R20.\nM30\n');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
    const readout = () => page.evaluate(() => {
      const p = document.querySelector('#plot .ncurve-measure');
      return p && !p.hidden ? p.innerText : '';
    });
    // a click at machine point m as the view shows it (on the canvas, not under the readout or
    // another box); the readout after it
    const hidden = [];
    const clickAt = async (m) => {
      const at = await page.evaluate((m) => {
        const p = ncurveWorkbench.plot.screenOfPoint(m);
        return Object.assign(p, {canvas: document.elementFromPoint(p.x, p.y) === ncurveWorkbench.plot.renderer.domElement});
      }, m);
      if (!at.canvas) hidden.push(m);
      await page.mouse.click(at.x, at.y);
      return readout();
    };
    const fitTop = () => page.evaluate(() => { ncurveWorkbench.plot.setView('top'); ncurveWorkbench.plot.render(); });
    await page.setViewportSize({width: 1024, height: 768});
    await page.waitForTimeout(200);
    await fitTop();
    await page.click('#views button:text-is("Measure")');
    check(/click a point of the path/.test(await readout()) && await page.evaluate(() => ncurveWorkbench.plot.measure.on),
          'the Measure button opens the readout');
    await clickAt([0, 0, -1]);
    let text = await clickAt([30, 40, -1]);
    check(/distance 50\.000 mm/.test(text) && /ΔX 30\.000\s+ΔY 40\.000\s+ΔZ 0\.000/.test(text) && /1: X0 Y0 Z-1 · end of line 2/.test(text) &&
          /2: X30 Y40 Z-1 · end of block N40 line 4/.test(text), `top view: X0 Y0 to X30 Y40, ends snapped: ${JSON.stringify(text)}`);
    const mid = [50 - 20 * Math.SQRT1_2, 40 + 20 * Math.SQRT1_2, -1];
    text = await clickAt(mid);
    check(/1: X35\.858 Y54\.142 Z-1 · on line 5 · arc radius 20\.000, centre X50 Y40 Z-1/.test(text) && !/distance/.test(text),
          `a third click starts again, on the arc: its radius and centre: ${JSON.stringify(text)}`);
    text = await clickAt([50, 60, -1]);
    check(/distance 15\.307 mm/.test(text), `from the arc's middle to its end 15.307: ${JSON.stringify(text)}`);
    await page.screenshot({path: path.join(out, 'workbench-measure-1024.png')});
    // off the path in the top view: the point of the XY plane under the pointer (at the first point's Z)
    await clickAt([0, 0, -1]);
    text = await clickAt([10, 30, -1]);
    check(/2: X10 Y30 Z-1 · off the path, in the view's plane \(Z as point 1\)/.test(text) && /distance 31\.623/.test(text), `off the path, the plane's point: ${JSON.stringify(text)}`);
    // iso: on the path only; the top of the plunge (X0 Y0 Z5) apart from its foot
    await page.evaluate(() => { ncurveWorkbench.plot.setView('iso'); ncurveWorkbench.plot.render(); });
    await clickAt([0, 0, 5]);
    text = await clickAt([30, 40, -1]);
    check(/distance 50\.359 mm/.test(text) && /ΔZ -6\.000/.test(text), `iso: X0 Y0 Z5 to X30 Y40 Z-1 (sqrt(2536) = 50.359): ${JSON.stringify(text)}`);
    const empty = await page.evaluate(() => { const r = ncurveWorkbench.plot.renderer.domElement.getBoundingClientRect(); return {x: r.right - 40, y: r.top + r.height / 2}; });
    await page.mouse.click(empty.x, empty.y);
    check(/no move under the pointer/.test(await readout()), 'iso: a click off the path picks nothing');
    await page.evaluate(() => document.activeElement && document.activeElement.blur());
    await page.keyboard.press('Escape');
    check(await readout() === '' && !(await page.evaluate(() => ncurveWorkbench.plot.measure.on)), 'Esc leaves Measure');
    await page.keyboard.press('m');
    check(/click a point/.test(await readout()), 'the key M opens it again');
    await page.setViewportSize({width: 1920, height: 1080});
    await page.waitForTimeout(200);
    await fitTop();
    await clickAt([0, 0, -1]);
    text = await clickAt([30, 40, -1]);
    check(/distance 50\.000 mm/.test(text), 'at 1920 x 1080 too');
    await page.mouse.move(5, 5);
    await page.screenshot({path: path.join(out, 'workbench-measure-1920.png')});
    check(hidden.length === 0, `every point clicked on the canvas, none under the readout or a box (${JSON.stringify(hidden)})`);
    await page.keyboard.press('m');
    await page.setViewportSize({width: 1024, height: 768});
    await page.waitForTimeout(200);

    // axis numbers at every zoom: 10 wheel notches in over the arc's middle, then 10 out from the
    // fitted view; each time at least 3 numbers on X and Y, inside the canvas, at a 1, 2 or 5 x 10^n
    // step, each where its value is on the screen
    const axisNumbers = () => page.evaluate(() => {
      const B = ncurveWorkbench.plot;
      B.render();
      const c = B.renderer.domElement.getBoundingClientRect(), out = {};
      for (const [k, axis] of [[0, 'x'], [1, 'y']]) {
        out[axis] = [...document.querySelectorAll(`#plot .ncurve-label.tick-${axis}`)].filter((e) => e.style.display !== 'none').map((e) => {
          const r = e.getBoundingClientRect(), v = Number(e.textContent), p = [0, 0, -1];
          p[k] = v;
          const at = B.screenOfPoint(p);
          return {v, inside: r.left >= c.left && r.right <= c.right && r.top >= c.top && r.bottom <= c.bottom,
            off: k === 0 ? Math.abs((r.left + r.right) / 2 - at.x) : Math.abs((r.top + r.bottom) / 2 - at.y)};
        });
      }
      return out;
    });
    const decade = (step) => { const m = step / Math.pow(10, Math.floor(Math.log10(step) + 1e-9)); return [1, 2, 5].some((d) => Math.abs(m - d) < 1e-6); };
    const numbersOk = (nums, what) => {
      for (const axis of ['x', 'y']) {
        const list = nums[axis], steps = list.slice(1).map((e, i) => e.v - list[i].v);
        const step = steps[0];
        check(list.length >= 3 && list.every((e) => e.inside && e.off < 2 && Number.isFinite(e.v)) && decade(step) &&
              steps.every((d) => Math.abs(d - step) < step * 1e-6),
              `${what}: ${axis.toUpperCase()} numbered ${list.map((e) => e.v).join(' ')} (step ${step}), inside the canvas, each at its value (${Math.max(...list.map((e) => e.off)).toFixed(1)} px off)`);
      }
    };
    const labelsClear = async (what) => {
      const overlapping = await labelsOverlapping();
      check(overlapping.length === 0, `${what}: no number or axis name over another (${overlapping.join(', ')})`);
    };
    await page.evaluate(() => { ncurveWorkbench.plot.setView('top'); ncurveWorkbench.plot.render(); });
    const over = await page.evaluate((m) => ncurveWorkbench.plot.screenOfPoint(m), mid);
    await page.mouse.move(over.x, over.y);
    const zoom = () => page.evaluate(() => ncurveWorkbench.plot.state().camera.zoom);
    let z0 = await zoom();
    for (let i = 0; i < 10; i++) await page.mouse.wheel(0, -100);
    await page.waitForFunction((z) => ncurveWorkbench.plot.state().camera.zoom > z * 6, z0);
    numbersOk(await axisNumbers(), 'zoomed in 10 notches');
    await labelsClear('zoomed in 10 notches');
    await page.screenshot({path: path.join(out, 'workbench-zoomed-in.png')});
    await page.evaluate(() => { ncurveWorkbench.plot.setView('top'); ncurveWorkbench.plot.render(); });
    z0 = await zoom();
    for (let i = 0; i < 10; i++) await page.mouse.wheel(0, 100);
    await page.waitForFunction((z) => ncurveWorkbench.plot.state().camera.zoom < z / 6, z0);
    numbersOk(await axisNumbers(), 'zoomed out 10 notches');
    await labelsClear('zoomed out 10 notches');
    await page.screenshot({path: path.join(out, 'workbench-zoomed-out.png')});
    // one rapid, from the home X250 Y200 Z400 to X54 Z2, in the Iso view zoomed out 12 notches: its
    // axes a few px long, their names side by side, none over another
    before = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('.wb-input', 'G00 X54. Z2.\nM30\n');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
    await page.evaluate(() => { ncurveWorkbench.plot.setView('iso'); ncurveWorkbench.plot.render(); });
    const off = await page.evaluate(() => { const r = ncurveWorkbench.plot.renderer.domElement.getBoundingClientRect(); return {x: r.left + r.width * 0.37, y: r.top + r.height * 0.41}; });
    await page.mouse.move(off.x, off.y);
    for (let i = 0; i < 12; i++) await page.mouse.wheel(0, 100);
    await page.waitForTimeout(100);
    await labelsClear('one rapid, Iso, zoomed out 12 notches');
    await page.screenshot({path: path.join(out, 'workbench-axes-names.png')});

    // holes: G81 at X10 Y10, X20 Y10, X30 Y10, then G91 X10 K3 on from there: X40, X50, X60 (Y10),
    // R-8 from the initial Z10 and Z-7 from there keeping point R at Z2; the pocket's entry (a plunge,
    // then a cut across) is none
    before = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('.wb-input', 'G17 G21 G90 G0 X0 Y0 Z10.\nG1 Z-1. F100.\nX5.\nG0 Z10.\nG99 G81 X10. Y10. Z-5. R2. F100.\nX20.\nX30.\n' +
      'G91 X10. R-8. Z-7. K3\nG80 G90 G0 Z10.\nM30\n');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
    const holes = await page.evaluate(() => ({list: ncurveWorkbench.plot.state().holes,
      legend: document.querySelector('#legend .holes') && document.querySelector('#legend .holes').textContent}));
    const expected = [10, 20, 30, 40, 50, 60].map((x) => [x, 10, 2]);
    check(JSON.stringify(holes.list) === JSON.stringify(expected) && holes.legend === '⊕holes 6',
          `holes marked at ${JSON.stringify(holes.list)} (the R plane, Z2), legend "${holes.legend}"`);
    // a marker drawn at each: a dark pixel at the hole's centre in the top view, none between two
    await page.mouse.move(5, 5);
    await fitTop();
    const dark = async (m) => {
      const at = await page.evaluate((m) => ncurveWorkbench.plot.screenOfPoint(m), m);
      const png = await page.screenshot({clip: {x: Math.round(at.x) - 1, y: Math.round(at.y) - 1, width: 3, height: 3}});
      return page.evaluate(async (b64) => {
        const img = new Image();
        img.src = 'data:image/png;base64,' + b64;
        await img.decode();
        const c = document.createElement('canvas');
        c.width = c.height = 3;
        const g = c.getContext('2d');
        g.drawImage(img, 0, 0);
        const d = g.getImageData(0, 0, 3, 3).data;
        let least = 765;
        for (let i = 0; i < d.length; i += 4) least = Math.min(least, d[i] + d[i + 1] + d[i + 2]);
        return least;
      }, png.toString('base64'));
    };
    const atHoles = [];
    for (const h of expected) atHoles.push(await dark(h));
    const between = await dark([15, 20, 2]);
    check(atHoles.every((v) => v < 150) && between > 600, `a dark mark on each hole (${atHoles.join(' ')}), none off them (${between})`);
    await page.screenshot({path: path.join(out, 'workbench-holes.png')});
    await page.setViewportSize({width: 1000, height: 700});

    // the editor cleared: an empty plot and a calm note, no request and no error
    for (const empty of ['', '%\n\n%\n']) {
      before = await page.evaluate(() => ncurveWorkbench.runs);
      await page.fill('.wb-input', empty);
      await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
      const e = await page.evaluate(() => ({status: document.getElementById('status').textContent,
        cls: document.getElementById('status').className, moves: ncurveWorkbench.moveCount, none: ncurveWorkbench.summary.none,
        summary: document.getElementById('summary').textContent, diags: ncurveWorkbench.diagnostics.length}));
      check(e.status === 'no program' && !/alarm/.test(e.cls) && e.moves === 0 && e.none && /no program/.test(e.summary) && e.diags === 0,
            `the editor holding ${JSON.stringify(empty)}: "${e.status}", ${e.moves} moves, summary "${e.summary}"`);
    }
    await page.screenshot({path: path.join(out, 'workbench-empty.png')});
    // two bad blocks: the run alarms at line 2 and reads line 3 as a text problem, which the answer
    // lists first; the list under the editor is in the text's order, the alarm marked
    before = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('.wb-input', 'G00 X1.\nG01 X[[1]\nG01 Y[[2]\nM30\n');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
    const listed = await page.evaluate(() => [...document.querySelectorAll('#diags li')].map((li) =>
      ({where: li.querySelector('.where').textContent, alarm: li.classList.contains('alarm')})));
    const answered = await page.evaluate(() => ncurveWorkbench.diagnostics.map((d) => d.line));
    check(answered.join() === '3,2' && listed.length === 2 && /:2:/.test(listed[0].where) && listed[0].alarm &&
          /:3:/.test(listed[1].where) && !listed[1].alarm,
          `the diagnostics listed by line, the alarm (line 2) first and marked: ${JSON.stringify(listed)} (answered ${answered})`);
    check(errors.length === 0, `still no script errors (${errors.join('; ')})`);
  }, async () => {
    await close();
    server.kill();
  });
})();
