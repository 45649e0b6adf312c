// The workbench's Part: `ncurve serve examples/spiral.nc` offers spiral.setup.toml beside it (not as
// a program); ticking Part cuts that setup's stock and draws the part under the path; the debugger
// at its start shows the stock uncut and at its end cut again; a rapid into the stock typed in the
// editor is listed at its line, and clicking it marks the place on the part. Screenshots looked at
// go to OUT_DIR. Exit 77 (skipped) where no Chromium is installed.
'use strict';
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

(async () => {
  const {server, port} = await serve(ncurve, [path.join(src, 'examples/spiral.nc')]);
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  await finish({check, counts, out}, async () => {
    const {page, errors} = await newPage(context);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1 && ncurveWorkbench.trace);
    const menu = await page.evaluate(() => [...document.getElementById('file').options].map((o) => o.value));
    check(menu.join() === 'spiral.nc', `the program menu lists the program, not its setup: ${menu}`);
    check(await page.evaluate(() => ncurveWorkbench.plot.state().part === 0), 'no part before Part is ticked');

    let runs = await page.evaluate(() => ncurveWorkbench.runs);
    await page.check('#part');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.part && ncurveWorkbench.part.moves === Infinity, runs);
    let P = await page.evaluate(() => ncurveWorkbench.part);
    // the setup's 40 x 40 block on 1000 x 1000 cells, drawn a point for each 3 x 3 cells (at most
    // 400 a side): 334 x 334 points
    check(P.triangles === 2 * 333 * 333 + 2 * 4 * 333, `the part drawn (${P.triangles} triangles)`);
    // the groove: 3 mm wide, 0.5 deep along 53.5 mm of feed, less its overlaps: between 60 and 81 mm³
    check(P.volume > 60 && P.volume < 81 && P.findings === 0, `the groove removed ${P.volume} mm³, ${P.findings} findings`);
    await page.screenshot({path: path.join(out, 'workbench-part.png')});

    // the debugger at the start: nothing cut; at the end: the whole groove again
    await page.evaluate(() => { ncurveWorkbench.setTab('debug'); ncurveWorkbench.goTo(0); });
    await page.waitForFunction(() => ncurveWorkbench.part.moves === 0);
    P = await page.evaluate(() => ncurveWorkbench.part);
    check(P.volume === 0, `at the first block the stock is uncut (${P.volume} mm³)`);
    const full = P;
    await page.evaluate(() => ncurveWorkbench.goTo(Infinity));
    await page.waitForFunction(() => ncurveWorkbench.part.moves > 0);
    P = await page.evaluate(() => ncurveWorkbench.part);
    check(P.volume > 60 && full.volume === 0, `at the end the groove is cut again (${P.volume} mm³)`);
    await page.evaluate(() => ncurveWorkbench.setTab('summary'));

    // the design's curve: the spiral groove's walls measured (the chords' sagitta, 6.9 um, each way),
    // beyond 5 um listed, the part coloured near its walls
    runs = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('#design', 'spiral tol=0.005');
    await page.dispatchEvent('#design', 'change');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.part && ncurveWorkbench.part.curve &&
      ncurveWorkbench.part.moves === Infinity, runs);
    P = await page.evaluate(() => ncurveWorkbench.part);
    check(P.curve.design === 'groove' && P.curve.largest_gouge_mm > 0.0065 && P.curve.largest_gouge_mm < 0.008 &&
          P.curve.largest_left_mm > 0.0065 && P.curve.largest_left_mm < 0.008,
          `the walls against the spiral: ${JSON.stringify(P.curve).slice(0, 300)}`);
    check(P.findings === 2, `beyond 5 um: a gouge and stock left listed (${P.findings})`);
    check(P.deviated && P.deviated.within > 1000 && P.deviated.gouge > 0 && P.deviated.left > 0,
          `the part coloured by the walls' errors: ${JSON.stringify(P.deviated)}`);
    await page.evaluate(() => { ncurveWorkbench.plot.setView('top'); ncurveWorkbench.plot.render(); });
    await page.screenshot({path: path.join(out, 'workbench-part-design.png')});
    runs = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('#design', 'spiral pitch');
    await page.dispatchEvent('#design', 'change');
    await page.waitForFunction(() => /design: "pitch": write NAME=VALUE/.test(document.getElementById('status').textContent));
    check(true, 'a bad design field is said in the status');
    await page.fill('#design', '');
    await page.dispatchEvent('#design', 'change');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.part && !ncurveWorkbench.part.curve, runs);

    // a rapid into the block: listed at its line; a click marks its place
    runs = await page.evaluate(() => ncurveWorkbench.runs);
    await page.fill('.wb-input', 'M03 S1000\nG90 G00 X0 Y0 Z5.\nG00 Z-1.\nG00 Z5.\nM30\n');
    await page.waitForFunction((n) => ncurveWorkbench.runs > n && ncurveWorkbench.settled(), runs);
    const listed = await page.evaluate(() => [...document.querySelectorAll('#diags li')].map((li) => li.textContent));
    const i = listed.findIndex((t) => /:3:1NC2080 a rapid removes material: 1\.000 mm deep/.test(t));
    check(i >= 0, `the rapid into the stock listed at line 3: ${JSON.stringify(listed)}`);
    await page.click(`#diags li >> nth=${Math.max(i, 0)}`);
    const at = await page.evaluate(() => ({line: ncurveWorkbench.editor.cursorLine(), at: ncurveWorkbench.findingShown}));
    check(at.line === 3 && at.at && Math.hypot(at.at[0], at.at[1]) <= 1.5 && Math.abs(at.at[2] + 1) < 1e-9,
          `the click goes to line 3 and marks the place on the part: ${JSON.stringify(at)}`);
    await page.screenshot({path: path.join(out, 'workbench-part-finding.png')});
    check(errors.length === 0, `no script errors (${errors.join('; ')})`);
  }, async () => {
    await close();
    server.kill();
  });
})();
