// The workbench of `ncurve serve --machine fanuc-lathe` in a real browser, on a shipped lathe example.
//   node workbench-lathe.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Checks: the server's profile selected, the moves drawn against `ncurve run --json`, the ZX view
// with Z across and X up (drawn as a radius, labelled as a diameter), a hovered move's end as the
// program writes it, the G71 block making its roughing in one step, the debugger's keys, its modal
// line's codes written as the control's screen writes them (two digits: G00, G01), and the
// system variables a program reads in the watch, a programmed arc under tool-nose radius compensation
// drawn on its circle and the nose circle about the nose centre at the end; with no FILE, the shipped
// lathe example. Screenshots go to OUT_DIR. Exit 77 without Chromium.
'use strict';
const {execFileSync} = require('child_process');
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

const file = path.join(src, 'examples/lathe-mrc.nc');
const run = (...a) => execFileSync(ncurve, ['run', file, '--machine', 'fanuc-lathe', ...a], {encoding: 'utf8'});
const summary = JSON.parse(run('--json'));
// the motions as `run --format jsonl` writes them (X a diameter), each with its start and end
const motions = run('--format', 'jsonl').trim().split('\n').map((l) => JSON.parse(l))
  .filter((m) => m.kind === 'rapid' || m.kind === 'line' || m.kind === 'arc')
  .map((m) => ({line: m.line, kind: m.kind, start: {x: m.start[0], z: m.start[2]}, end: {x: m.end[0], z: m.end[2]}}));
const shown = (v) => String(Number(v.toFixed(3)));  // as the page writes a number

// serve --machine fanuc-lathe with no FILE: the shipped lathe example, run on the lathe
async function latheExample(context) {
  const {server, port} = await serve(ncurve, ['--machine', 'fanuc-lathe']);
  try {
    const page = await context.newPage();
    page.setDefaultTimeout(60000);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    const w = await page.evaluate(() => ({text: ncurveWorkbench.editor.text, ok: ncurveWorkbench.summary.ok,
      file: document.getElementById('file').selectedOptions[0].text, view: ncurveWorkbench.plot.state().view}));
    const example = require('fs').readFileSync(path.join(src, 'examples/lathe-hyperbola.nc'), 'utf8');
    check(w.text === example && w.ok && w.file === 'lathe-hyperbola.nc (example)' && w.view === 'zx',
          `no FILE on a lathe: the lathe example (${w.file}), completed (${w.ok}), in the ZX view`);
    await page.close();
  } finally {
    server.kill();
  }
}

(async () => {
  const {server, port} = await serve(ncurve, ['--machine', 'fanuc-lathe', file]);
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  await finish({check, counts, out}, async () => {
    const {page, errors} = await newPage(context);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1);
    const W = () => page.evaluate(() => ({runs: ncurveWorkbench.runs, moveCount: ncurveWorkbench.moveCount,
      pos: ncurveWorkbench.pos, line: ncurveWorkbench.state && ncurveWorkbench.state.line, reads: ncurveWorkbench.reads,
      readChanged: ncurveWorkbench.readChanged, state: ncurveWorkbench.plot.state(), drawnUpTo: ncurveWorkbench.drawnUpTo,
      count: ncurveWorkbench.trace && ncurveWorkbench.trace.count}));

    // the profile serve was given, the moves of `run`
    check(await page.evaluate(() => document.getElementById('machine').value) === 'fanuc-lathe',
          'serve --machine fanuc-lathe: the page runs on fanuc-lathe');
    let w = await W();
    check(summary.ok && w.moveCount === summary.motions && motions.length === summary.motions,
          `${w.moveCount} moves drawn, the run made ${summary.motions}`);
    // the extents as `ncurve run` says them: X(dia) on a lathe programmed in diameters
    const extents = await page.evaluate(() => {
      const dt = [...document.querySelectorAll('#summary dt')].find((d) => d.textContent === 'extents');
      return dt ? dt.nextElementSibling.textContent : '';
    });
    const ext = summary.extent, textRun = run();
    check(extents === `X(dia) ${shown(ext.X[0])} … ${shown(ext.X[1])}   Z ${shown(ext.Z[0])} … ${shown(ext.Z[1])}` &&
          /extent X\(dia\)/.test(textRun), `the extents as run says them: ${extents}`);
    check(w.state.kinds.feed === summary.moves.line && w.state.kinds.rapid === summary.moves.rapid &&
          w.state.kinds.arc === summary.moves.arc, `moves by kind ${JSON.stringify(w.state.kinds)}`);

    // the ZX view: screen x a linear function of Z, screen y of X (up), one scale for Z and the radius
    check(w.state.view === 'zx', `the ZX view by default (${w.state.view})`);
    const screen = await page.evaluate(() => Array.from({length: ncurveWorkbench.plot.moves.count}, (_, i) => ncurveWorkbench.plot.screenOf(i)));
    const fit = (xs, ys) => {  // least squares y = a x + b, and the largest residual
      const n = xs.length, mx = xs.reduce((s, v) => s + v, 0) / n, my = ys.reduce((s, v) => s + v, 0) / n;
      let sxy = 0, sxx = 0;
      for (let i = 0; i < n; i++) sxy += (xs[i] - mx) * (ys[i] - my), sxx += (xs[i] - mx) ** 2;
      const a = sxy / sxx, b = my - a * mx;
      return {a, worst: Math.max(...xs.map((x, i) => Math.abs(a * x + b - ys[i])))};
    };
    // the feed lines (a rapid is drawn as the machine moves it, a dog-leg whose middle is a corner)
    const straight = motions.map((m, i) => ({m, s: screen[i]})).filter((o) => o.m.start && o.m.kind === 'line');
    const mid = (o, k) => (o.m.start[k] + o.m.end[k]) / 2;
    const across = fit(straight.map((o) => mid(o, 'z')), straight.map((o) => o.s.x));
    const up = fit(straight.map((o) => mid(o, 'x') / 2), straight.map((o) => o.s.y));  // radius
    check(across.a > 0 && across.worst < 1.5, `Z across, to the right (${across.a.toFixed(3)} px/mm, off by ${across.worst.toFixed(2)} px)`);
    check(up.a < 0 && up.worst < 1.5, `X up (${(-up.a).toFixed(3)} px/mm of radius, off by ${up.worst.toFixed(2)} px)`);
    check(Math.abs(across.a + up.a) < 0.01 * across.a, 'the same scale on Z and on the radius: the part in true proportion');
    const names = await page.evaluate(() => [...document.querySelectorAll('.axis-name')]
      .filter((e) => e.style.display !== 'none').map((e) => { const r = e.getBoundingClientRect(); return {t: e.textContent, x: r.left, y: r.top}; }));
    const xName = names.find((n) => n.t.startsWith('X')), zName = names.find((n) => n.t.startsWith('Z'));
    check(xName && /diameter/.test(xName.t) && zName && xName.y < zName.y && zName.x > xName.x,
          `the axes named: ${JSON.stringify(names.map((n) => n.t))}`);

    // Part ticked: the bar of lathe-mrc.setup.toml (beside the program) cut and drawn revolved, the
    // volume `run --setup` gives; unticked again for what follows
    const verified = JSON.parse(run('--setup', path.join(src, 'examples/lathe-mrc.setup.toml'), '--json')).verify;
    let partRuns = await page.evaluate(() => ncurveWorkbench.runs);
    await page.check('#part');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.part && ncurveWorkbench.part.moves === Infinity, partRuns);
    const P = await page.evaluate(() => ncurveWorkbench.part);
    check(P.triangles > 0 && P.triangles % 192 === 0 && Math.abs(P.volume - verified.volume_removed_mm3) < 1e-6 * verified.volume_removed_mm3 &&
          P.findings === 0, `the lathe's part drawn revolved (${P.triangles} triangles), ${P.volume} mm³ removed as run says`);
    await page.screenshot({path: path.join(out, 'workbench-lathe-part.png')});
    partRuns = await page.evaluate(() => ncurveWorkbench.runs);
    await page.uncheck('#part');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), partRuns);
    check(await page.evaluate(() => ncurveWorkbench.plot.state().part === 0), 'Part unticked: no part drawn');

    // a hovered move says where it ends as the program writes it: X a diameter, Z, no Y
    const target = await page.evaluate(() => {
      const B = ncurveWorkbench.plot, n = B.moves.count, r = B.renderer.domElement.getBoundingClientRect();
      const pts = Array.from({length: n}, (_, i) => B.screenOf(i));
      for (let i = 1; i < n; i++) {
        const p = pts[i];
        if (B.moves.kind[i] === 2 || p.x < r.left + 60 || p.y < r.top + 60 || p.x > r.right - 60 || p.y > r.bottom - 60) continue;
        if (pts.every((q, j) => j === i || Math.hypot(q.x - p.x, q.y - p.y) > 6)) return {i, p};
      }
      return null;
    });
    check(target !== null, 'a move to hover');
    if (target) {
      await page.mouse.move(target.p.x, target.p.y);
      await page.waitForTimeout(150);
      const tip = await page.evaluate(() => document.getElementById('hover').textContent);
      // the move under the pointer: the one aimed at, or a move whose line passes as near the point
      const hovered = await page.evaluate(() => ncurveWorkbench.plot.state().hovered);
      const m = motions[hovered >= 0 ? hovered : target.i];
      check(tip.includes(`to X${shown(m.end.x)} Z${shown(m.end.z)}`) && !/ Y/.test(tip),
            `hovering move ${hovered + 1} (aimed at ${target.i + 1}) shows its end X${shown(m.end.x)} Z${shown(m.end.z)} (${tip})`);
      // the tip beside the pointer, inside the plot, not over the pointer nor an axis name
      const at = await page.evaluate(() => {
        const r = (e) => e.getBoundingClientRect();
        return {tip: r(document.getElementById('hover')).toJSON(), plot: r(document.getElementById('plot')).toJSON(),
          names: [...document.querySelectorAll('.ncurve-label.axis-name')].filter((e) => e.style.display !== 'none').map((e) => r(e).toJSON())};
      });
      const t = at.tip, p = target.p, overlaps = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
      const near = Math.hypot(Math.max(t.left - p.x, 0, p.x - t.right), Math.max(t.top - p.y, 0, p.y - t.bottom));
      check(t.left >= at.plot.left && t.right <= at.plot.right && t.top >= at.plot.top && t.bottom <= at.plot.bottom &&
            near > 0 && near < 40 && !at.names.some((n) => overlaps(n, t)),
            `the tip beside the pointer (${near.toFixed(0)} px off), inside the plot, clear of the axis names`);
      await page.screenshot({path: path.join(out, 'workbench-lathe-hover.png')});
      await page.mouse.move(5, 500);
    }

    // the debugger: G71 (line 9) makes all its roughing in one step; the next block is the one after
    // N200 (line 19), as FANUC goes on after the shape's last block
    await page.click('button[data-tab="debug"]');
    const g71 = await page.evaluate(() => {
      const t = ncurveWorkbench.trace;
      for (let k = 0; k < t.count; k++) if (t.at(k).line === 9) return k;
      return -1;
    });
    check(g71 > 0, `line 9 (G71) executed (block ${g71 + 1})`);
    await page.evaluate((k) => ncurveWorkbench.goTo(k), g71);
    await page.evaluate(() => document.activeElement && document.activeElement.blur());
    const before9 = motions.filter((m) => m.line < 9).length, upTo9 = motions.filter((m) => m.line <= 9).length;
    w = await W();
    check(w.drawnUpTo === before9, `before G71, the ${before9} motions of lines 7 drawn (${w.drawnUpTo})`);
    await page.keyboard.press('F10');
    w = await W();
    check(w.pos === g71 + 1 && w.line === 19 && w.drawnUpTo === upTo9,
          `F10: one block on, on line ${w.line} (19) with the ${upTo9} motions up to G71's drawn (${w.drawnUpTo})`);
    await page.screenshot({path: path.join(out, 'workbench-lathe.png')});
    // the modal line as the system-A lathe has its groups: G99 (line 7) is feed per revolution, no
    // G98 beside it, no G90/G91 group (G90 is a turning cycle there); the count is the summary's
    const gs = (await page.textContent('#dbg-modal')).split('\n')[0].split(' ');
    check(gs.includes('G99') && gs.includes('G18') && !gs.includes('G98') && !gs.includes('G90') && !gs.includes('G91'),
          `the modal line on a system-A lathe: ${gs.join(' ')}`);
    // written as the control's screen writes them, two digits before the point: G00 or G01 in group 01
    check(gs.every((g) => /^G\d\d(\.\d)?$/.test(g)) && /^G0[0-3]$/.test(gs[0]), `each code with two digits (${gs[0]} ...)`);
    const words = (await page.textContent('#dbg-modal')).split('\n')[1].split(' ');
    check(words.includes('F0.25') && words.includes('T0101') && !words.some((w) => /^[DH]/.test(w)),
          `the lathe's modal words, no D or H offset (a mill's): ${words.join(' ')}`);
    const counted = await page.textContent('#dbg-pos');
    check(counted.includes(`of ${summary.blocks_executed} `),
          `the debugger counts the summary's ${summary.blocks_executed} blocks executed (${counted})`);
    await page.keyboard.press('Shift+F10');
    w = await W();
    check(w.pos === g71 && w.line === 9, `Shift+F10: one block back, on line ${w.line}`);
    await page.keyboard.press('ArrowRight');
    w = await W();
    check(w.pos === g71 + 1, `→: one block on (${w.pos})`);
    await page.keyboard.press('ArrowLeft');
    w = await W();
    check(w.pos === g71, `←: one block back (${w.pos})`);
    await page.keyboard.press('End');
    w = await W();
    check(w.pos === w.count, `End: after the last block (${w.pos} of ${w.count})`);
    await page.keyboard.press('Home');
    w = await W();
    check(w.pos === 0, `Home: the start (${w.pos})`);
    // F5 / Shift+F5: a breakpoint on line 26 (G75)
    const g = await page.evaluate(() => ncurveWorkbench.editor.gutterOf(26));
    await page.mouse.click(g.x, g.y);
    await page.keyboard.press('F5');
    w = await W();
    check(w.line === 26, `F5: on to the breakpoint on line 26 (${w.line})`);
    await page.keyboard.press('Shift+F5');
    w = await W();
    check(w.pos === 0, `Shift+F5: back, no breakpoint before: the start (${w.pos})`);
    // in the editor an arrow moves the cursor, not the debugger; F10 still steps
    await page.evaluate(() => ncurveWorkbench.editor.input.focus());
    await page.keyboard.press('ArrowRight');
    w = await W();
    check(w.pos === 0, `→ in the editor leaves the debugger where it is (${w.pos})`);
    await page.keyboard.press('F10');
    w = await W();
    check(w.pos === 1, `F10 in the editor steps (${w.pos})`);

    // the system variables read, by hand: G00 to X40. (a diameter) Z5.: #5001 reads 40, #5002 5;
    // after G01 X30. Z-10., #5002 reads -10; after G02, #4001 reads 2
    const prog = 'G00 X40. Z5.\n#100=#5001\n#101=#5002\nG01 X30. Z-10. F0.2\n#102=#5002\nG02 X40. Z-15. R5.\n#103=#4001\nM30\n';
    const runs = w.runs;
    await page.evaluate((t) => { ncurveWorkbench.editor.setText(t); document.getElementById('run').click(); }, prog);
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), runs);
    await page.evaluate(() => { ncurveWorkbench.goTo(0); document.activeElement && document.activeElement.blur(); });
    const row = (v) => page.evaluate((n) => {
      const r = document.querySelector(`.wb-vars tr[data-sys="${n}"]`);
      return r && {text: r.textContent, name: r.cells[0].textContent, value: r.cells[1].textContent, changed: r.classList.contains('changed')};
    }, v);
    w = await W();
    check(w.reads && Object.keys(w.reads).length === 0 && !(await row(5001)), 'at the start no system variable read');
    for (let i = 0; i < 2; i++) await page.keyboard.press('ArrowRight');  // after line 2
    w = await W();
    let r = await row(5001);
    check(w.line === 3 && w.reads['#5001'] === 40 && w.readChanged.includes('#5001') && r && r.changed &&
          r.name === '#5001 end point X' && r.value === '40', `after #100=#5001: #5001 = ${w.reads['#5001']} (40), named and in yellow (${r && r.name}: ${r && r.value})`);
    await page.keyboard.press('F10');  // after line 3
    w = await W();
    r = await row(5001);
    check(w.reads['#5002'] === 5 && r && !r.changed, `after #101=#5002: #5002 = ${w.reads['#5002']} (5), #5001 no longer in yellow`);
    for (let i = 0; i < 2; i++) await page.keyboard.press('F10');  // after line 5
    w = await W();
    r = await row(5002);
    check(w.reads['#5002'] === -10 && r && r.changed, `after G01 and #102=#5002: #5002 = ${w.reads['#5002']} (-10), in yellow`);
    for (let i = 0; i < 2; i++) await page.keyboard.press('F10');  // after line 7
    w = await W();
    r = await row(4001);
    check(w.reads['#4001'] === 2 && r && r.name === '#4001 G group 1' && r.changed, `after G02 and #103=#4001: #4001 = ${w.reads['#4001']} (2), ${r && r.name}`);
    await page.screenshot({path: path.join(out, 'workbench-lathe-watch.png')});
    await page.keyboard.press('Shift+F10');
    w = await W();
    check(w.reads['#4001'] === undefined && w.reads['#5002'] === -10, 'one block back: #4001 not read yet');
    // Measure in the ZX view, X as the profile programs it (a diameter): X⌀40 Z5 to X⌀30 Z-10 is
    // ΔX⌀ -10 ΔZ -15, a true distance of sqrt(5^2 + 15^2) = 15.811; the G02 X40. Z-15. R5. from X⌀30
    // Z-10 turns clockwise seen from +Y (Z right, X up) about X⌀40 Z-10
    await page.evaluate(() => { ncurveWorkbench.plot.setView('zx'); ncurveWorkbench.plot.render(); });
    await page.click('#views button:text-is("Measure")');
    const measure = async (m) => {
      const at = await page.evaluate((m) => ncurveWorkbench.plot.screenOfPoint(m), m);
      await page.mouse.click(at.x, at.y);
      return page.evaluate(() => document.querySelector('#plot .ncurve-measure').innerText);
    };
    await measure([20, 0, 5]);
    let said = await measure([15, 0, -10]);
    check(/1: X⌀40 Z5 · end of line 1/.test(said) && /2: X⌀30 Z-10 · end of line 4/.test(said) && /distance 15\.811 mm/.test(said) &&
          /ΔX⌀ -10\.000\s+ΔZ -15\.000/.test(said) && !/Y/.test(said), `lathe Measure, X a diameter: ${JSON.stringify(said)}`);
    said = await measure([20, 0, -15]);
    check(/1: X⌀40 Z-15 · end of line 6 · arc radius 5\.000, centre X⌀40 Z-10/.test(said), `the arc's radius and centre: ${JSON.stringify(said)}`);
    await page.screenshot({path: path.join(out, 'workbench-lathe-measure.png')});
    await page.keyboard.press('Escape');
    // a watchpoint on #5002, a variable read: stops where a read gets a new value (5 after line 3,
    // -10 after line 5), not at a block that reads nothing new
    await page.fill('#watch-var', '#5002');
    await page.click('#watch-add');
    await page.waitForSelector('#watches .w');
    await page.click('#dbg-first');
    await page.keyboard.press('F5');
    w = await W();
    check(w.line === 4 && w.reads['#5002'] === 5, `F5 with #5002 watched: stops after line 3 (on ${w.line}, #5002 = ${w.reads['#5002']})`);
    await page.keyboard.press('F5');
    w = await W();
    check(w.line === 6 && w.reads['#5002'] === -10, `and after line 5 (on ${w.line}, #5002 = ${w.reads['#5002']})`);

    // tool-nose radius compensation, fanuc-lathe's offset 1 (nose R 0.4, tip 3): the programmed quarter
    // arc about X0 Z-10 (I0 K-10) from X0 Z0 to X20 (a diameter) Z-10 drawn dashed on its circle of
    // radius 10; after the last block the tip at X40 Z-30 and the nose circle of 0.4 about the nose
    // centre, tip 3 putting the tip at -X -Z of it: X radius 20.4, Z -29.6
    const before = (await W()).runs;
    await page.evaluate((t) => { ncurveWorkbench.editor.setText(t); document.getElementById('run').click(); },
      'T0101\nG00 X0 Z5.\nG42 G01 X0 Z0 F0.1\nG03 X20. Z-10. I0 K-10.\nG01 Z-30.\nG40 G00 X40.\nM30\n');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
    const dashed = await page.evaluate(() => ncurveWorkbench.plot.programmedPoints());
    let onArc = 0, off = 0;
    for (let v = 0; v < dashed.length; v += 3) {
      const x = dashed[v], z = dashed[v + 2];
      if (z < -1e-4 && z > -10 + 1e-4) (Math.abs(Math.hypot(x, z + 10) - 10) < 1e-3 ? onArc++ : off++);
    }
    check(onArc >= 8 && off === 0, `the programmed arc dashed on its circle about X0 Z-10: ${onArc} points on it, ${off} off`);
    await page.evaluate(() => ncurveWorkbench.goTo(Infinity));
    const nose = await page.evaluate(() => ({text: document.getElementById('dbg-tool').innerText, points: ncurveWorkbench.plot.cutterPoints()}));
    let round = nose.points.length >= 3 * 32;
    for (let v = 0; v < nose.points.length; v += 3)
      round = round && Math.abs(Math.hypot(nose.points[v] - 20.4, nose.points[v + 2] + 29.6) - 0.4) < 1e-5;
    check(/T0101/.test(nose.text) && /offset 1 nose R 0\.4 mm/.test(nose.text) && /tip 3/.test(nose.text) && round,
          `after the last block: "${nose.text.replace(/\n/g, ' · ')}", the nose circle 0.4 about X(radius) 20.4 Z-29.6`);
    check(errors.length === 0, `no script errors (${errors.join('; ')})`);
    await latheExample(context);
  }, async () => {
    await close();
    server.kill();
  });
})();
