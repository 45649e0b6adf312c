// The workbench's colour modes in a real browser: headless Chromium (Debian's), playwright-core.
//   node colour.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Starts `ncurve serve --port 0 examples/spiral.nc`, colours the moves by the feed reached (the
// colours vary, the legend's scale has numbers in mm/min, rapids grey), then generates an ellipse
// in the Generate tab: the curve drawn in grey under the path (its points as /api/gen gave them,
// through a change of view), each move on the curve coloured by its deviation (at most the
// tolerance), and once the program is edited, colours by kind with the legend saying why.
// Screenshots workbench-feed.png and workbench-gen-deviation.png in OUT_DIR. Exit 77 (skipped)
// where no Chromium is installed.
'use strict';
const fs = require('fs');
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

// Lines at F6000 (100 mm/s) of 0.5 to 32 mm in a zigzag: on the mill's 1000 mm/s^2 a line needs 5 mm
// to reach the feed from rest, and the corners slow it, so the feed reached varies.
const zigzag = path.join(out, 'zigzag.nc');
fs.writeFileSync(zigzag, ['%', 'O0001', 'G90 G17 G21', 'G00 X0. Y0. Z5.', 'G01 Z-1. F500.', 'G91 F6000.',
  ...[0.5, 1, 2, 4, 8, 16, 32].map((L, k) => `X${(k % 2 ? -L : L).toFixed(1)} Y1.`), 'G90 G00 Z5.', 'M30', '%', ''].join('\n'));

(async () => {
  const {server, port} = await serve(ncurve, [path.join(src, 'examples/spiral.nc'), zigzag]);
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  await finish({check, counts, out}, async () => {
    const {page, errors} = await newPage(context);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1);
    const colour = () => page.evaluate(() => ncurveWorkbench.colour);
    const legend = () => page.evaluate(() => document.getElementById('legend').textContent);

    // feed reached: the zigzag's moves coloured on the scale 0 .. its programmed feed
    await page.evaluate(() => ncurveWorkbench.open('zigzag.nc'));
    await page.selectOption('#colour', 'feed');
    await page.waitForFunction(() => ncurveWorkbench.colour && ncurveWorkbench.colour.mode === 'feed' && ncurveWorkbench.colour.scale);
    let c = await colour();
    const feedMoves = await page.evaluate(() => {
      const s = ncurveWorkbench.plot.state().kinds;
      return s.feed + s.arc;
    });
    check(c.coloured === feedMoves, `every move at feed coloured by its feed (${c.coloured} of ${feedMoves})`);
    check(c.distinct > 3, `the colours vary along the path (${c.distinct} colours)`);
    check(c.scale.unit === 'mm/min' && c.scale.max === 6000 && c.most > 0 && c.most <= c.scale.max,
          `scale 0 .. ${c.scale.max} mm/min, highest feed reached ${c.most}`);
    const text = await legend();
    check(text.includes('mm/min') && c.ticks.length === 5 && c.ticks.every((t) => text.includes(t)) &&
          c.ticks[0] === '0' && Number(c.ticks[4]) === c.scale.max, `the legend shows the scale with numbers (${text})`);
    // rapids grey: the colour of a rapid as drawn
    const rapidGrey = await page.evaluate(() => {
      const B = ncurveWorkbench.plot, k = B.moves.kind;
      for (let i = 0; i < B.moves.count; i++) if (k[i] === 0) return true;
      return null;
    });
    check(rapidGrey === null || c.grey.includes('rapids grey'), `rapids drawn grey (${c.grey})`);
    await page.screenshot({path: path.join(out, 'workbench-feed.png')});

    // generate an ellipse with G01 lines: the curve in grey, the moves coloured by deviation
    await page.click('button[data-tab="gen"]');
    await page.selectOption('#gen-curve', 'ellipse');
    await page.fill('#gen-fields input[data-param="a"]', '20');
    await page.fill('#gen-fields input[data-param="b"]', '10');
    await page.fill('#gen-tol', '0.005');
    await page.selectOption('#gen-form', 'expanded');
    const runs = await page.evaluate(() => ncurveWorkbench.runs);
    await page.click('#gen');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.colour && ncurveWorkbench.colour.mode === 'deviation', runs);
    const gen = await page.evaluate(async () => {
      const r = await fetch('/api/gen', {method: 'POST', headers: {'Content-Type': 'application/json'},
        body: JSON.stringify({curve: 'ellipse', params: {a: 20, b: 10}, tol: 0.005, form: 'expanded'})});
      return r.json();
    });
    c = await colour();
    let state = await page.evaluate(() => ncurveWorkbench.plot.state());
    check(state.reference === gen.reference.count && state.reference > 100,
          `the curve drawn in grey: ${state.reference} points (the answer's ${gen.reference.count})`);
    check(await page.evaluate(() => document.getElementById('colour').value) === 'deviation', 'the selector says deviation');
    check(c.scale.max === 0.005 && c.scale.unit === 'mm', `deviation scale 0 .. ${c.scale.max} ${c.scale.unit}`);
    check(c.coloured === gen.move_deviation.index.length, `each move on the curve coloured (${c.coloured} of ${gen.move_deviation.index.length})`);
    check(c.most > 0 && c.most <= 0.005 && Math.abs(c.most - gen.max_deviation) < 1e-9,
          `max deviation shown ${c.most} mm <= 0.005, gen's ${gen.max_deviation}`);
    check(c.distinct > 3, `the deviation colours vary (${c.distinct} colours)`);
    const gtext = await legend();
    check(gtext.includes('deviation') && gtext.includes('0.005') && gtext.includes('max 0.00'), `the legend: ${gtext}`);
    await page.click('button[data-view="top"]');
    state = await page.evaluate(() => ncurveWorkbench.plot.state());
    check(state.view === 'top' && state.reference === gen.reference.count, 'the curve stays through a change of view');
    await page.screenshot({path: path.join(out, 'workbench-gen-deviation.png')});

    // edited: colours by kind, the legend says so; the curve stays
    const before = await page.evaluate(() => ncurveWorkbench.runs);
    await page.evaluate(() => ncurveWorkbench.editor.setText(ncurveWorkbench.editor.text.replace('M30', 'M05\nM30')));
    await page.click('#run');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
    await page.waitForTimeout(100);
    c = await colour();
    check(c.mode === 'deviation' && !c.scale && c.coloured === 0 && /edited/.test(await legend()),
          `edited: coloured by kind, the legend says why (${await legend()})`);
    state = await page.evaluate(() => ncurveWorkbench.plot.state());
    check(state.reference === gen.reference.count, 'the curve still drawn under the edited program');
    await page.screenshot({path: path.join(out, 'workbench-gen-edited.png')});
    check(errors.length === 0, `no script errors (${errors.join('; ')})`);
  }, async () => {
    await close();
    server.kill();
  });
})();
