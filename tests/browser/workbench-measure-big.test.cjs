// Measure on a big path: 1,001,002 moves, a zigzag of 1000 rows of 1000 feeds of 0.1 mm each (row
// j at Y = 0.1 j, even rows towards +X, odd ones back), 0.1 mm apart: X and Y 0 .. 100 mm. Zoomed in
// about X50 Y50 in the top view, two clicks snap to the ends X50 Y50 (row 500) and X50.3 Y50.1
// (row 501): 0.316 mm apart (sqrt(0.3^2 + 0.1^2)), ΔX 0.3, ΔY 0.1, worked by hand; a click looks at
// fewer than 1 in 1000 of the path's segments (its grid index, backplot-snap.js), and a click on a
// move's middle gives the point of the move there.
//   node workbench-measure-big.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
'use strict';
const fs = require('fs');
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, , out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

(async () => {
  const small = path.join(out, 'measure-small.nc'), big = path.join(out, 'measure-big.nc');
  fs.writeFileSync(small, 'G90 G17 G21 G00 X0 Y0 Z1.\nG01 X10. F100.\nM30\n');
  fs.writeFileSync(big, [
    'G90 G17 G21 G00 X0 Y0 Z1.', 'G01 Z0 F1000.', '#2=0',
    'WHILE [#2 LT 1000] DO1',
    '#3=#2-FIX[#2/2]*2',  // 0 on an even row, 1 on an odd one
    '#1=1',
    'WHILE [#1 LE 1000] DO2',
    'G01 X[#3*100+[1-2*#3]*#1*0.1]',
    '#1=#1+1', 'END2',
    'G01 Y[[#2+1]*0.1]',
    '#2=#2+1', 'END1', 'M30', ''].join('\n'));
  const {server, port} = await serve(ncurve, [small, big]);
  const {context, close} = await launch(driver, chromium, {width: 1024, height: 768});
  await finish({check, counts, out}, async () => {
    const {page, errors} = await newPage(context, 300000);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    // no trace for a million moves: the Debugger off, then the big program
    let n = await page.evaluate(() => ncurveWorkbench.runs);
    await page.uncheck('#trace');
    await page.waitForFunction((k) => ncurveWorkbench.runs > k && ncurveWorkbench.settled(), n);
    n = await page.evaluate(() => ncurveWorkbench.runs);
    await page.selectOption('#file', 'measure-big.nc');
    await page.waitForFunction((k) => ncurveWorkbench.runs > k && ncurveWorkbench.settled() && ncurveWorkbench.name === 'measure-big.nc', n);
    const count = await page.evaluate(() => ncurveWorkbench.moveCount);
    check(count === 1001002, `the big path drawn: ${count} moves (2 + 1000 rows of 1000 and a step)`);
    await page.evaluate(() => { ncurveWorkbench.plot.setView('top'); ncurveWorkbench.plot.render(); });
    // 28 wheel notches in about X50 Y50 (1.2^28, about 165 times the fit of 100 mm in some 600 px):
    // 0.1 mm about 100 px, the ends far apart against the 8 px a click snaps within
    const at = (m) => page.evaluate((m) => ncurveWorkbench.plot.screenOfPoint(m), m);
    let p = await at([50, 50, 0]);
    await page.mouse.move(p.x, p.y);
    for (let i = 0; i < 28; i++) await page.mouse.wheel(0, -100);
    await page.evaluate(() => ncurveWorkbench.plot.render());
    await page.click('#views button:text-is("Measure")');
    const click = async (m) => {
      const q = await at(m);
      await page.mouse.click(q.x, q.y);
      return page.evaluate(() => ncurveWorkbench.plot.measure.state());
    };
    let s = await click([50, 50, 0]);
    s = await click([50.3, 50.1, 0]);
    check(s.points.length === 2 && s.points.every((q) => q.snap === 'end'), `both clicks snapped to ends: ${JSON.stringify(s.points.map((q) => q.snap))}`);
    check(/distance 0\.316 mm/.test(s.text) && /ΔX 0\.300\s+ΔY 0\.100\s+ΔZ 0\.000/.test(s.text) && /1: X50 Y50 Z0/.test(s.text) &&
          /2: X50\.3 Y50\.1 Z0/.test(s.text), `X50 Y50 to X50.3 Y50.1: ${JSON.stringify(s.text)}`);
    check(s.looked > 0 && s.looked * 1000 < s.segments, `the last click looked at ${s.looked} of ${s.segments} segments`);
    // the middle of the feed from X50.3 to X50.4 on row 501 (Y50.1): on it, at X50.35
    s = await click([50.35, 50.1, 0]);
    const q = s.points[0];
    check(s.points.length === 1 && q.snap === 'on' && Math.abs(q.at[0] - 50.35) < 0.002 && Math.abs(q.at[1] - 50.1) < 1e-4,
          `a third click starts again, on the move: ${JSON.stringify(q)}`);
    await page.screenshot({path: path.join(out, 'workbench-measure-big.png')});
    check(errors.length === 0, `no script errors (${errors.join(' | ')})`);
  }, async () => { await close(); server.kill(); });
})();
