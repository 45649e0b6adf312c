// What a run asks of the Settings, in a real browser: headless Chromium (Debian's), playwright-core.
//   node workbench-asked.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// On `ncurve serve examples/`: Max steps that is not a whole number refused beside its field in
// `run --max-steps`'s words (run in the test), with no request made; spiral.nc stopped by Max steps
// 50 (NC9000, "raise --max-steps"): the CLI's message with the page's pointer "(here: the Settings
// tab, Max steps)" in the diagnostics and the Summary, and a button opening the Settings tab at the
// field. custom-cycle.nc, whose RUN comment asks for --lib macros --param 6050=102: the note under
// the editor names both; the server has no such folder, so it says to start it with --lib FOLDER,
// and its button puts the parameter in the Settings (the run then alarms as the CLI's without
// --lib). On `ncurve serve --lib macros examples/` with the folder unticked: the note names the
// folder and the parameter, and its button ticks the one and sets the other: the run completes as
// the CLI's with both (361 G01 moves: the plunge and the cycle's 360), the note gone.
'use strict';
const {spawnSync} = require('child_process');
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();
const examples = path.join(src, 'examples');
const example = (n) => path.join(examples, n);
const macros = path.join(src, 'macros');
// `ncurve run FILE ARGS --json`: its summary (exit 1 on an alarm is an answer too); its refusal's line
const cli = (file, args) => JSON.parse(spawnSync(ncurve, ['run', file, ...args, '--json'], {encoding: 'utf8'}).stdout);
const cliError = (file, args) => spawnSync(ncurve, ['run', file, ...args], {encoding: 'utf8'}).stderr.split('\n')[0].trim();

(async () => {
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  const servers = [];
  await finish({check, counts, out}, async () => {
    // the page of `ncurve serve ARGS` and its helpers
    const open = async (args) => {
      const {server, port} = await serve(ncurve, args);
      servers.push(server);
      const {page, errors: all} = await newPage(context);
      const errors = () => all.filter((e) => !/status of 4\d\d/.test(e));  // the refusals asked for
      const requests = [];
      page.on('request', (r) => { if (r.url().endsWith('/api/run')) requests.push(r.postData()); });
      await page.goto(`http://127.0.0.1:${port}/`);
      await page.waitForFunction(() => window.ncurveWorkbench && ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
      const runs = () => page.evaluate(() => [ncurveWorkbench.runs, ncurveWorkbench.refusals]);
      // a run shown, or refused
      const ran = ([r, f]) => page.waitForFunction(([r, f]) => (ncurveWorkbench.runs > r && ncurveWorkbench.settled()) ||
        ncurveWorkbench.refusals > f, [r, f]);
      // no run going nor one in its 300 ms wait (a change of the Settings starts one of its own)
      const quiet = async () => {
        await page.waitForFunction(() => ncurveWorkbench.settled());
        await page.waitForTimeout(400);
        await page.waitForFunction(() => ncurveWorkbench.settled());
      };
      const setting = async (id, value) => {
        await page.waitForFunction(() => ncurveWorkbench.settled());
        const k = await runs();
        await page.fill(id, value);
        await page.locator(id).dispatchEvent('change');
        await ran(k);
      };
      const choose = async (name) => {
        const k = await runs();
        await page.selectOption('#file', name);
        await ran(k);
        await page.waitForFunction((m) => ncurveWorkbench.name === m && ncurveWorkbench.settled(), name);
      };
      const text = (id) => page.evaluate((i) => document.getElementById(i).textContent, id);
      const note = () => page.evaluate(() => {
        const box = document.getElementById('runline'), s = ncurveWorkbench.summary;
        return {shown: !box.hidden, text: box.textContent, apply: (box.querySelector('.wb-runline-apply') || {}).textContent || '',
          param: document.getElementById('set-param').value, ok: s.ok, alarm: s.alarm && s.alarm.code, lines: s.moves.line,
          motions: s.motions};
      });
      return {page, errors, requests, runs, ran, quiet, setting, choose, text, note};
    };

    // ---- serve examples/: Max steps checked as the command line checks it ----
    let p = await open([examples]);
    await p.page.click('button[data-tab="settings"]');
    for (const bad of ['abc', '1.5', '0']) {
      const sent = p.requests.length;
      await p.setting('#set-steps', bad);
      const why = await p.text('set-steps-why'), cliWhy = cliError(example('spiral.nc'), ['--max-steps', bad]);
      check(why === cliWhy && p.requests.length === sent, `Max steps ${bad}: "${why}" beside the field, as the CLI's ` +
            `"${cliWhy}"; ${p.requests.length - sent} requests made`);
    }
    check(await p.page.getAttribute('#set-steps', 'aria-invalid') === 'true' && /--max-steps/.test(await p.text('status')),
          `the field marked, the status: ${await p.text('status')}`);

    // NC9000 after 50 steps: the CLI's message, the page's pointer and its button to the field
    await p.setting('#set-steps', '50');
    // (the CLI names the file as it was given, the page by its name)
    const stopped = cli(example('spiral.nc'), ['--max-steps', '50']).alarm;
    stopped.message = stopped.message.split(example('spiral.nc')).join('spiral.nc');
    await p.page.click('button[data-tab="summary"]');
    const row = await p.page.evaluate(() => {
      const li = [...document.querySelectorAll('#diags li')].find((l) => l.querySelector('strong').textContent === 'NC9000');
      return li ? {text: li.textContent, go: li.querySelector('button') ? li.querySelector('button').textContent : ''} : null;
    });
    const pointer = ' (here: the Settings tab, Max steps)';
    check(stopped.code === 'NC9000' && /raise --max-steps/.test(stopped.message) && !stopped.message.includes('here:') && row &&
          row.text.includes(' ' + stopped.message + pointer) && row.go === 'Settings: Max steps',
          `NC9000: the CLI's message "${stopped.message}", in the page with its pointer (${row && row.text})`);
    const [result, summary] = await p.page.evaluate(() => [document.querySelector('#summary dd').textContent,
      document.getElementById('summary').textContent]);
    check(result.includes(stopped.message + pointer) && !summary.includes('"max_steps"'),
          `the Summary's result, in the command line's words: ${result}`);
    await p.page.click('#diags li button');
    const at = await p.page.evaluate(() => ({tab: !document.getElementById('tab-settings').hidden, focus: document.activeElement.id}));
    check(at.tab && at.focus === 'set-steps', `its button opens the Settings tab at Max steps (${JSON.stringify(at)})`);
    await p.setting('#set-steps', '');
    check((await p.note()).ok && await p.text('set-steps-why') === '', 'Max steps cleared: spiral.nc completes, no message');

    // custom-cycle.nc asks for --lib macros --param 6050=102; this server has no macro folder
    const noLib = cli(example('custom-cycle.nc'), ['--param', '6050=102']);
    const both = cli(example('custom-cycle.nc'), ['--lib', macros, '--param', '6050=102']);
    await p.choose('custom-cycle.nc');
    let n = await p.note();
    check(n.shown && /--param 6050=102/.test(n.text) && /--lib macros/.test(n.text) && /start the server with --lib FOLDER/.test(n.text) &&
          n.apply === 'Apply --param 6050=102', `custom-cycle.nc on serve examples/: the note "${n.text}" (button "${n.apply}")`);
    await p.page.screenshot({path: path.join(out, 'workbench-runline-options-1400.png')});
    let k = await p.runs();
    await p.page.click('#runline .wb-runline-apply');
    await p.ran(k);
    await p.quiet();
    n = await p.note();
    check(n.param === '6050=102' && !n.ok && n.alarm === noLib.alarm.code && n.shown && !n.apply && /--lib FOLDER/.test(n.text) &&
          !/--param/.test(n.text), `applied: the Settings' parameters "${n.param}", ALARM ${n.alarm} as the CLI's without --lib ` +
          `(${noLib.alarm.code}), the note left: "${n.text}"`);
    check(p.errors().length === 0, `no script errors (${p.errors().join(' | ')})`);
    await p.page.close();

    // ---- serve --lib macros examples/, the folder unticked: the button ticks it and sets 6050 ----
    p = await open(['--lib', macros, examples]);
    await p.page.click('button[data-tab="settings"]');
    k = await p.runs();
    await p.page.uncheck(`#set-libs input[value="${macros}"]`);
    await p.ran(k);
    await p.quiet();
    await p.choose('custom-cycle.nc');
    n = await p.note();
    check(n.shown && n.text.includes(`--lib ${macros}`) && /--param 6050=102/.test(n.text) && !/FOLDER/.test(n.text) && n.apply === 'Apply them',
          `custom-cycle.nc on serve --lib macros examples/, the folder unticked: the note "${n.text}"`);
    k = await p.runs();
    await p.page.click('#runline .wb-runline-apply');
    await p.ran(k);
    await p.quiet();
    n = await p.note();
    const ticked = await p.page.isChecked(`#set-libs input[value="${macros}"]`);
    check(both.ok && n.ok && n.lines === both.moves.line && n.lines === 361 && n.motions === both.motions && ticked &&
          n.param === '6050=102' && !n.shown,
          `applied: the folder ticked (${ticked}), 6050=102, completed with ${n.lines} G01 moves as the CLI's (${both.moves.line}), the note gone`);
    check(p.errors().length === 0, `no script errors (${p.errors().join(' | ')})`);
  }, async () => { await close(); for (const s of servers) s.kill(); });
})();
