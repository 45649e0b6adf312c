// The workbench's Compare tab: two versions of a program written here, served by `ncurve serve`.
//   node workbench-compare.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Checks, against the programs' own coordinates: the run kept, one coordinate edited in the editor
// lists exactly that block with its old and new end; a line inserted lists it as inserted and
// nothing else; the other file (the server's, after Revert drops the edits above, then the same text
// from this computer) lists the
// blocks worked out below, those after an edited G91 increment grouped as moved by its offset; an
// entry clicked selects its line and highlights its moves; the other run drawn grey and the view
// fitted to it, not when hidden. Screenshots workbench-compare-1024.png, -1920.png in OUT_DIR.
// Exit 77 without Chromium.
'use strict';
const fs = require('fs');
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, , out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

// A: a G90 path (lines 4 to 9: an arc by R from X30 Y20 to X10 Y20), then G91 increments from X0 Y0
const A = ['%', 'O1000 (COMPARE A)', 'G17 G90', 'G00 X0. Y0. Z5.', 'G01 Z-1. F100.', 'G01 X30. Y0.', 'G01 X30. Y20.',
  'G02 X10. Y20. R10.', 'G01 X0. Y0. F200.', 'G91 G01 X5. F100.', 'G01 Y5.', 'G01 X-5.', 'G90 G00 Z5.', 'M30', '%', ''];
// B against A: its title (no move), line 6 to X90., a line more after the arc (9, a line to X5 Y20),
// line 10 (A's 9) at F250, the first increment (line 11, A's 10) X6.: the three blocks after it end
// 1 mm further in X (A's 11 to 13)
const B = ['%', 'O1000 (COMPARE B)', 'G17 G90', 'G00 X0. Y0. Z5.', 'G01 Z-1. F100.', 'G01 X90. Y0.', 'G01 X30. Y20.',
  'G02 X10. Y20. R10.', 'G01 X5. Y20.', 'G01 X0. Y0. F250.', 'G91 G01 X6. F100.', 'G01 Y5.', 'G01 X-5.', 'G90 G00 Z5.',
  'M30', '%', ''];
const dir = path.join(out, 'compare');
fs.mkdirSync(dir, {recursive: true});
fs.writeFileSync(path.join(dir, 'compare-a.nc'), A.join('\n'));
fs.writeFileSync(path.join(dir, 'compare-b.nc'), B.join('\n'));

(async () => {
  const {server, port} = await serve(ncurve, [path.join(dir, 'compare-a.nc'), path.join(dir, 'compare-b.nc')]);
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  await finish({check, counts, out}, async () => {
    const {page, errors} = await newPage(context);
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    await page.click('button[data-tab="compare"]');
    // the list made for the text in the editor, the other run not being run
    const compared = () => page.waitForFunction(() => {
      const W = ncurveWorkbench;
      return W.settled() && W.compare.text === W.editor.text && !W.compare.running;
    });
    const C = () => page.evaluate(() => ncurveWorkbench.compare);
    // the text typed in place of `from` on a line (1-based)
    const typeOver = async (line, from, text) => {
      await page.evaluate(([line, from]) => {
        const ed = ncurveWorkbench.editor, t = ed.text.split('\n'), at = t.slice(0, line - 1).join('\n').length + 1 + t[line - 1].indexOf(from);
        ed.input.focus();
        ed.input.setSelectionRange(at, at + from.length);
      }, [line, from]);
      await page.keyboard.type(text);
      await compared();
    };

    // 1. kept, then X30. of line 6 made X32.: line 6 alone (line 7 starts elsewhere, its own move alike)
    await page.click('#cmp-keep');
    await compared();
    let c = await C();
    check(c.source === 'kept' && c.same && c.count === 0 && /^the same moves as the run kept at/.test(await page.textContent('#cmp-count')),
      `kept: the same moves (${c.count}, "${await page.textContent('#cmp-count')}")`);
    check(c.drawn > 0, `the kept run drawn in grey (${c.drawn} segments)`);
    await typeOver(6, '30.', '32.');
    c = await C();
    const e1 = c.entries[0];
    check(c.count === 1 && c.entries.length === 1 && e1.kind === 'changed' && e1.was === 6 && e1.now === 6 &&
      e1.what === 'end X30.000 → X32.000' && e1.text === 'G01 X32. Y0.' && e1.old === 'G01 X30. Y0.' && !e1.after.length,
      `one coordinate edited: exactly line 6 listed, X30 → X32 (${JSON.stringify(c.entries)})`);
    await page.click('#cmp-list tr.changed');
    const picked = await page.evaluate(() => {
      const W = ncurveWorkbench, m = W.plot.moves, h = W.highlighted;
      return {line: W.editor.cursorLine(), h: h.map((j) => [m.line[j], m.end[3 * j], m.end[3 * j + 1]]), was: W.compare.highlighted.was.length};
    });
    check(picked.line === 6 && JSON.stringify(picked.h) === '[[6,32,0]]' && picked.was === 1,
      `its entry clicked: line 6 selected, its move to X32 Y0 highlighted, the kept one too (${JSON.stringify(picked)})`);

    // 2. kept again, a line inserted after line 6: listed as inserted (line 7 now), nothing else
    await page.click('#cmp-keep');
    await compared();
    check((await C()).same, 'the edited run kept: the same moves');
    await page.evaluate(() => {
      const ed = ncurveWorkbench.editor, at = ed.text.split('\n').slice(0, 6).join('\n').length;
      ed.input.focus();
      ed.input.setSelectionRange(at, at);
    });
    await page.keyboard.type('\nG01 X32. Y10.');
    await compared();
    c = await C();
    check(c.count === 1 && c.entries.length === 1 && c.entries[0].kind === 'inserted' && c.entries[0].was === 0 &&
      c.entries[0].now === 7 && c.entries[0].what === 'line to X32.000 Y10.000 Z-1.000',
      `a line inserted: listed as inserted at line 7, nothing else (${JSON.stringify(c.entries)})`);

    // 3. A from the server against compare-b.nc, run as the editor's program is (Revert: the edits
    // above dropped, the file read again)
    page.once('dialog', (d) => d.accept());
    await page.click('#revert');
    await page.waitForFunction(() => !ncurveWorkbench.edited.includes('compare-a.nc') && ncurveWorkbench.settled());
    await page.selectOption('#cmp-with', 'file:compare-b.nc');
    await page.waitForFunction(() => ncurveWorkbench.compare.source === 'file');
    await compared();
    const expected = [
      {kind: 'changed', was: 6, now: 6, what: 'end X90.000 → X30.000', after: []},
      {kind: 'deleted', was: 9, now: 0, text: 'G01 X5. Y20.', what: 'line to X5.000 Y20.000 Z-1.000', after: []},
      {kind: 'changed', was: 10, now: 9, what: 'F250 → F200', after: []},
      {kind: 'changed', was: 11, now: 10, what: 'end X6.000 → X5.000', shift: 'X-1.000', after: [[12, 11], [13, 12], [14, 13]]},
    ];
    const fileCase = (c) => {
      const got = c.entries.map((e) => ({kind: e.kind, was: e.was, now: e.now, what: e.what, text: e.text, shift: e.shift,
        after: e.after.map((x) => [x.was, x.now])}));
      const bad = expected.filter((x, k) => !got[k] || Object.keys(x).some((key) => JSON.stringify(x[key]) !== JSON.stringify(got[k][key])));
      return c.count === 7 && got.length === expected.length && !bad.length ? '' : JSON.stringify(got);
    };
    c = await C();
    let bad = fileCase(c);
    check(!bad && /^7 blocks differ from compare-b\.nc \(1 edited line makes no move\)$/.test(await page.textContent('#cmp-count')),
      `against compare-b.nc: line 6's end, 9 deleted, 10's feed, 11's increment and the 3 blocks after it moved by X-1 ${bad}`);
    const fold = await page.textContent('#cmp-list tr.fold');
    check(/^and 3 blocks after it, each moved by the same offset X-1\.000/.test(fold), `the moved blocks folded: "${fold}"`);
    await page.click('#cmp-list tr.fold');
    check(await page.evaluate(() => document.querySelectorAll('#cmp-list tr.moved:not([hidden])').length) === 3, 'unfolded: their 3 rows');
    // the view fits compare-b.nc's X90 too; without it drawn, only A's moves (X 0 to 30)
    const onCanvas = () => page.evaluate(() => {
      const r = document.querySelector('#plot canvas').getBoundingClientRect(), p = ncurveWorkbench.plot.screenOfPoint([90, 0, -1]);
      return p.x >= r.left && p.x <= r.right && p.y >= r.top && p.y <= r.bottom;
    });
    check(await onCanvas(), 'X90 Y0 of the other run inside the view');
    await page.uncheck('#cmp-draw');
    await page.waitForFunction(() => ncurveWorkbench.compare.drawn === 0);
    check(!(await onCanvas()), 'not drawn: the view fits the program alone, X90 off it');
    await page.check('#cmp-draw');
    await page.waitForFunction(() => ncurveWorkbench.compare.drawn > 0);
    await page.click('#cmp-list tr.deleted');
    const del = await page.evaluate(() => ({line: ncurveWorkbench.editor.cursorLine(), h: ncurveWorkbench.compare.highlighted}));
    check(del.line === 9 && del.h.now.length === 0 && del.h.was.length === 1,
      `the deleted block clicked: line 9 (where it was) selected, its move in the other run highlighted (${JSON.stringify(del)})`);
    const legend = await page.textContent('#legend');
    check(legend.includes('compared: compare-b.nc'), `the legend names the grey run: "${legend}"`);
    for (const [w, h] of [[1024, 768], [1920, 1080]]) {
      await page.setViewportSize({width: w, height: h});
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      const fits = await page.evaluate(() => {
        const p = document.getElementById('tab-compare').getBoundingClientRect();
        return [...document.querySelectorAll('#tab-compare button, #tab-compare select, #cmp-count, #cmp-list th')]
          .every((e) => { const r = e.getBoundingClientRect(); return r.left >= p.left && r.right <= p.right + 0.5; });
      });
      check(fits, `at ${w} x ${h} the tab's controls and the list's columns inside the panel`);
      await page.screenshot({path: path.join(out, `workbench-compare-${w}.png`)});
    }

    // the same text picked on this computer; an empty file refused, the comparison kept
    await page.setInputFiles('#cmp-file', {name: 'b-local.nc', mimeType: 'text/plain', buffer: Buffer.from(B.join('\n'))});
    await page.waitForFunction(() => ncurveWorkbench.compare.source === 'local');
    await compared();
    c = await C();
    bad = fileCase(c);
    check(!bad && c.label === 'b-local.nc (this computer)', `b-local.nc from this computer: the same list ${bad}`);
    await page.setInputFiles('#cmp-file', {name: 'empty.nc', mimeType: 'text/plain', buffer: Buffer.from('%\n\n%\n')});
    await page.waitForFunction(() => document.getElementById('cmp-status').textContent !== '');
    c = await C();
    check(await page.textContent('#cmp-status') === 'empty.nc: the file holds no program' && c.label === 'b-local.nc (this computer)' && c.count === 7,
      `an empty file refused beside the menu, the comparison kept (${await page.textContent('#cmp-status')})`);
    check(errors.length === 0, `no script errors (${errors.join('; ')})`);
  }, async () => {
    await close();
    server.kill();
  });
})();
