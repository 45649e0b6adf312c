// The workbench of `ncurve serve` on a 4-axis mill: the A axis, which the 3D view does not draw.
//   node workbench-rotary.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Serves examples/4-axis.nc on profiles/fanuc-4axis-helicoid.toml and checks, against values
// worked out from the program's text: the Summary naming A as not drawn with its range, a hovered
// move's end with its A; a program that leaves A at 0 shows neither. Screenshot
// workbench-rotary.png in OUT_DIR. Exit 77 without Chromium.
'use strict';
const fs = require('fs');
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

const file = path.join(src, 'examples/4-axis.nc');
const machine = path.join(src, 'profiles/fanuc-4axis-helicoid.toml');
// the program: G00 Y0. A0., G00 X0. Z25., G01 Z19. (#104-#105 = 20 - 1), then a loop of
// `G01 X[10*SIN[2*#1]] A#1` for #1 = 2, 4 ... 360: A from 0 to 360 degrees; its 45th turn is
// #1 = 90, X = 10 SIN[180] = 0, the program's 3 + 45 = 48th move
const lines = fs.readFileSync(file, 'utf8').split('\n');
const loopLine = lines.findIndex((l) => l.startsWith('G01 X[#101*SIN[#102*#1]] A#1')) + 1;

(async () => {
  const {server, port} = await serve(ncurve, ['--machine', machine, file]);
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  await finish({check, counts, out}, async () => {
    const {page, errors} = await newPage(context);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    const fact = (name) => page.evaluate((name) => {
      const dt = [...document.querySelectorAll('#summary dt')].find((d) => d.textContent === name);
      return dt ? dt.nextElementSibling.textContent : null;
    }, name);
    check(loopLine > 0, `the loop's G01 on line ${loopLine}`);
    check(await page.evaluate(() => ncurveWorkbench.summary.ok), 'the program completed');

    // the Summary: A not drawn, 0 to 360 degrees; the extents give A in degrees too
    const notDrawn = await fact('axes not drawn');
    check(notDrawn !== null && notDrawn.startsWith('A 0 … 360°'), `the Summary names A as not drawn, 0 … 360°: "${notDrawn}"`);
    const extents = await fact('extents');
    check(/(^| )A 0 … 360°/.test(extents || ''), `the extents give A in degrees: "${extents}"`);

    // the move to A90: the 45th move of the loop's line
    const i = await page.evaluate((line) => {
      const m = ncurveWorkbench.plot.moves;
      for (let j = 0, seen = 0; j < m.count; j++) if (m.line[j] === line && ++seen === 45) return j;
      return -1;
    }, loopLine);
    check(i >= 0, 'the 45th move of the loop');
    await page.evaluate((i) => ncurveWorkbench.plot.hover(i), i);
    const tip = await page.evaluate(() => document.getElementById('hover').textContent);
    check(tip.includes(`line ${loopLine}`) && tip.includes('move 48 ') && / to X0 Y0 Z19 A90$/.test(tip),
          `the hover text gives the move's end with its A: "${tip}"`);
    await page.screenshot({path: path.join(out, 'workbench-rotary.png')});
    await page.evaluate(() => ncurveWorkbench.plot.hover(-1));
    // X runs -9.994 ... 9.994: in the iso view numbered at a 1, 2 or 5 x 10^n step within that range,
    // 0 among them, at least three
    const xs = await page.evaluate(() => {
      const B = ncurveWorkbench.plot;
      B.setView('iso');
      B.render();
      return [...document.querySelectorAll('.ncurve-label.tick-x')].filter((e) => e.style.display !== 'none').map((e) => Number(e.textContent));
    });
    const step = xs[1] - xs[0], decade = step / Math.pow(10, Math.floor(Math.log10(step) + 1e-9));
    check(xs.length >= 3 && xs.includes(0) && xs.every((v, i) => Math.abs(v - (xs[0] + i * step)) < 1e-9 && Math.abs(v) <= 9.994) &&
          [1, 2, 5].some((d) => Math.abs(decade - d) < 1e-9), `the X axis numbered ${xs.join(' ')} in the iso view (step ${step})`);

    // a program that leaves A at 0: nothing said of it
    const before = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('.wb-input', 'G00 X10. Y5. Z2.\nG01 Z-1. F100.\nM30\n');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), before);
    await page.evaluate(() => ncurveWorkbench.plot.hover(1));
    const flat = await page.evaluate(() => document.getElementById('hover').textContent);
    check(await fact('axes not drawn') === null && / to X10 Y5 Z-1$/.test(flat),
          `A left at 0: not named in the Summary, not in the hover text ("${flat}")`);
    check(errors.length === 0, `no script errors (${errors.join('; ')})`);
  }, async () => {
    await close();
    server.kill();
  });
})();
