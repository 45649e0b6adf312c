// The program a served folder opens with: `ncurve serve examples/` lists 4-axis.nc first (by name),
// whose RUN comment asks for the 4-axis profile; the page opens spiral.nc instead, the program the
// README tours, which completes on the default mill. On `--machine fanuc-lathe` it opens
// lathe-hyperbola.nc, the lathe's example. Files given one by one open with the first of them when
// it asks for no other machine (alarm.nc, though it alarms: that is the program asked for). 4-axis.nc
// chosen on the mill: the note naming the machine it asks for, and its button choosing that machine.
//   node workbench-folder.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
'use strict';
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();
const examples = path.join(src, 'examples');

(async () => {
  const {context, close} = await launch(driver, chromium, {width: 1024, height: 768});
  const servers = [];
  await finish({check, counts, out}, async () => {
    // the page of `ncurve serve ARGS`: the program it opened, its menu, the summary
    const opened = async (args) => {
      const {server, port} = await serve(ncurve, args);
      servers.push(server);
      const {page, errors} = await newPage(context);
      await page.goto(`http://127.0.0.1:${port}/`);
      await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
      const r = await page.evaluate(() => ({name: ncurveWorkbench.name, chosen: document.getElementById('file').value,
        menu: [...document.getElementById('file').options].map((o) => o.value), ok: ncurveWorkbench.summary.ok,
        alarm: ncurveWorkbench.summary.alarm && ncurveWorkbench.summary.alarm.code}));
      r.errors = errors;
      await page.close();
      return r;
    };
    let r = await opened([examples]);
    check(r.menu[0] === '4-axis.nc' && r.name === 'spiral.nc' && r.chosen === 'spiral.nc' && r.ok,
          `serve examples/: ${r.name} opened (menu ${r.menu.join(' ')}), ${r.ok ? 'completed' : 'ALARM ' + r.alarm}`);
    r = await opened(['--machine', 'fanuc-lathe', examples]);
    check(r.name === 'lathe-hyperbola.nc' && r.chosen === 'lathe-hyperbola.nc' && r.ok,
          `serve --machine fanuc-lathe examples/: ${r.name}, ${r.ok ? 'completed' : 'ALARM ' + r.alarm}`);
    r = await opened([path.join(examples, 'alarm.nc'), path.join(examples, 'spiral.nc')]);
    check(r.name === 'alarm.nc' && r.chosen === 'alarm.nc', `serve alarm.nc spiral.nc: the first given, ${r.name}`);
    r = await opened([path.join(examples, '4-axis.nc'), path.join(examples, 'inch.nc')]);
    check(r.name === 'inch.nc' && r.chosen === 'inch.nc' && r.ok, `serve 4-axis.nc inch.nc: the first asking no other machine, ${r.name}`);
    check(r.errors.length === 0, `no script errors (${r.errors.join(' | ')})`);

    // 4-axis.nc chosen from the menu on the default mill: it alarms (no A axis), and the note under
    // the editor names the machine its RUN comment asks for; its button chooses it, and the program
    // completes: the plunge and 360 / 2 = 180 loop turns of G01, 181 feeds
    const {server, port} = await serve(ncurve, [examples]);
    servers.push(server);
    const {page, errors} = await newPage(context);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    const note = () => page.evaluate(() => ({shown: !document.getElementById('runline').hidden, text: document.getElementById('runline').textContent,
      machine: document.getElementById('machine').value, alarm: ncurveWorkbench.summary.alarm && ncurveWorkbench.summary.alarm.code,
      ok: ncurveWorkbench.summary.ok, feeds: ncurveWorkbench.plot.state().kinds.feed, runs: ncurveWorkbench.runs}));
    let n = await note();
    check(!n.shown, `spiral.nc asks for no machine: no note (${n.text})`);
    await page.selectOption('#file', '4-axis.nc');
    await page.waitForFunction((k) => ncurveWorkbench.runs > k && ncurveWorkbench.settled(), n.runs);
    n = await note();
    check(n.alarm === 'PS0009' && n.shown && /--machine fanuc-4axis-helicoid/.test(n.text),
          `4-axis.nc on the mill: ${n.alarm}, and the note "${n.text}"`);
    await page.screenshot({path: path.join(out, 'workbench-runline-1024.png')});
    await page.click('#runline button');
    await page.waitForFunction((k) => ncurveWorkbench.runs > k && ncurveWorkbench.settled(), n.runs);
    n = await note();
    check(n.machine === 'fanuc-4axis-helicoid' && n.ok && n.feeds === 181 && !n.shown,
          `its button: on ${n.machine}, ${n.ok ? 'completed' : 'ALARM ' + n.alarm}, ${n.feeds} feeds (181), the note gone`);
    check(errors.length === 0, `no script errors (${errors.join(' | ')})`);
  }, async () => { await close(); for (const s of servers) s.kill(); });
})();
