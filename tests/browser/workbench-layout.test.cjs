// The workbench at 1024 x 768 in a real browser, as a user on a small screen sees it: `ncurve serve
// examples/` on the mill and on `--machine fanuc-lathe`.
//   node workbench-layout.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Checks: the Debugger tab at block 16 shows its position on the buttons' row and the modal state
// (G codes, then F M S T) and the tool inside the panel, without scrolling, on both machines.
// Screenshots go to OUT_DIR. Exit 77 without Chromium.
'use strict';
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

// the debugger of the first program `serve ARGS` opens, at block 16
async function debuggerAt16(context, args, tag) {
  const {server, port} = await serve(ncurve, args);
  try {
    const {page, errors} = await newPage(context);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    await page.click('button[data-tab="debug"]');
    for (let i = 0; i < 15; i++) await page.click('#dbg-fwd');
    const r = await page.evaluate(() => {
      const box = (id) => document.getElementById(id).getBoundingClientRect();
      const panel = box('tab-debug'), modal = box('dbg-modal'), tool = box('dbg-tool'), pos = box('dbg-pos'), fwd = box('dbg-fwd');
      return {panel: panel.bottom, modal: modal.bottom, tool: tool.bottom, modalTop: modal.top, posRow: Math.abs(pos.top + pos.height / 2 - (fwd.top + fwd.height / 2)),
        lines: document.getElementById('dbg-modal').textContent.split('\n'), pos: document.getElementById('dbg-pos').textContent,
        scrolled: document.getElementById('tab-debug').scrollTop};
    });
    check(r.pos.startsWith('block 16 of') && r.posRow < 4, `${tag}: "${r.pos}" on the buttons' row (centres ${r.posRow.toFixed(1)} px apart)`);
    check(r.lines.length === 2 && /^G\d\d/.test(r.lines[0]) && /\bF\d/.test(r.lines[1]), `${tag}: the modal state, G codes then F M S T (${r.lines.join(' / ')})`);
    check(r.scrolled === 0 && r.modal <= r.panel && r.tool <= r.panel,
          `${tag}: the modal state (bottom ${r.modal.toFixed(0)}) and the tool (${r.tool.toFixed(0)}) inside the panel (${r.panel.toFixed(0)}), not scrolled`);
    check(errors.length === 0, `${tag}: no script errors (${errors.join('; ')})`);
    await page.screenshot({path: path.join(out, `workbench-debugger-${tag}-1024.png`)});
    await page.close();
  } finally {
    server.kill();
  }
}

(async () => {
  const {context, close} = await launch(driver, chromium, {width: 1024, height: 768});
  await finish({check, counts, out}, async () => {
    await debuggerAt16(context, [path.join(src, 'examples')], 'mill');
    await debuggerAt16(context, ['--machine', 'fanuc-lathe', path.join(src, 'examples')], 'lathe');
  }, close);
})();
