// The backplot's axes on a long thin part, in a real browser: the workbench of `ncurve serve` on a
// program the test writes (a feed from X0 Y0 to X200 Y5 at Z-1), at 1024 x 768.
//   node workbench-axes.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Checks, in the Top view: the Y axis, 5 mm long (about 10 px at the fit), numbered as X is (same
// scale, same step), its 0 level with the path's start; Z, seen end-on, not numbered; every tick mark
// on its axis' line; zoomed out ten notches, Y still numbered. Screenshots go to OUT_DIR.
// Exit 77 without Chromium.
'use strict';
const fs = require('fs');
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, , out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

const dir = fs.mkdtempSync(path.join(out, 'axes-'));
const thin = path.join(dir, 'thin.nc');
fs.writeFileSync(thin, '%\nO0001\nG90 G17 G21 G54\nG00 X0. Y0. Z5.\nG01 Z-1. F100.\nG01 X200. Y5. F500.\nG00 Z5.\nM30\n%\n');

(async () => {
  const {server, port} = await serve(ncurve, [thin]);
  const {context, close} = await launch(driver, chromium, {width: 1024, height: 768});
  await finish({check, counts, out}, async () => {
    const {page, errors} = await newPage(context);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    await page.click('#views button[data-view="top"]');
    await page.waitForTimeout(200);
    // the axes as shown, in canvas pixels, and where X0 Y0 Z-1 is
    const shown = () => page.evaluate(() => {
      const B = ncurveWorkbench.plot, r = B.renderer.domElement.getBoundingClientRect(), p = B.screenOfPoint([0, 0, -1]);
      return {axes: B.state().axes, origin: [p.x - r.left, p.y - r.top]};
    });
    let s = await shown();
    const ys = s.axes.values[1], xs = s.axes.values[0];
    check(ys.length >= 3, `Top view at the fit: the 5 mm Y axis numbered (${ys.join(' ')}), as X (${xs.join(' ')})`);
    check(s.axes.steps[1] === s.axes.steps[0], `Y's step that of X, the same scale (${s.axes.steps[1]}, ${s.axes.steps[0]})`);
    const zero = ys.indexOf(0);
    check(zero >= 0 && Math.abs(s.axes.numbers[1][zero][1] - s.origin[1]) < 1.5,
          `Y's 0 level with the path's start (y ${zero >= 0 ? s.axes.numbers[1][zero][1].toFixed(1) : '-'}, ${s.origin[1].toFixed(1)})`);
    check(s.axes.values[2].length === 0, `Z, seen end-on, not numbered (${s.axes.values[2].join(' ')})`);
    // every tick mark on its axis' line: its place between the line's ends
    const offLine = (a) => {
      const bad = [];
      for (let k = 0; k < 3; k++) {
        const L = a.lines[k];
        if (!L) continue;
        const [[x0, y0], [x1, y1]] = L, len = Math.hypot(x1 - x0, y1 - y0) || 1;
        for (const [x, y] of a.marks[k]) {
          const t = ((x - x0) * (x1 - x0) + (y - y0) * (y1 - y0)) / (len * len);
          const d = Math.abs((x - x0) * (y1 - y0) - (y - y0) * (x1 - x0)) / len;
          if (t < -0.5 / len || t > 1 + 0.5 / len || d > 0.5) bad.push(`${'XYZ'[k]} (${x.toFixed(0)}, ${y.toFixed(0)})`);
        }
      }
      return bad;
    };
    let bad = offLine(s.axes);
    check(bad.length === 0, `every tick mark on its axis' line (off it: ${bad.join(' ')})`);
    await page.screenshot({path: path.join(out, 'workbench-axes-thin.png')});

    // zoomed out about the canvas' centre: Y numbered still
    const box = await page.locator('#plot canvas').boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    for (let i = 0; i < 10; i++) await page.mouse.wheel(0, 100);
    await page.waitForTimeout(300);
    s = await shown();
    check(s.axes.values[1].length >= 2, `zoomed out: Y numbered (${s.axes.values[1].join(' ')}), X (${s.axes.values[0].join(' ')})`);
    bad = offLine(s.axes);
    check(bad.length === 0, `zoomed out: every tick mark on its axis' line (off it: ${bad.join(' ')})`);
    await page.screenshot({path: path.join(out, 'workbench-axes-thin-out.png')});
    check(errors.length === 0, `no script errors (${errors.join('; ')})`);
  }, async () => {
    await close();
    server.kill();
    fs.rmSync(dir, {recursive: true, force: true});
  });
})();
