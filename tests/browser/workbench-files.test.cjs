// The workbench's files and Settings in a real browser: headless Chromium (Debian's), playwright-core.
//   node workbench-files.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Starts `ncurve serve --port 0 examples/spiral.nc examples/alarm.nc examples/custom-cycle.nc --lib
// macros` and checks: Save and Ctrl+S download the editor's text byte for byte, named as the
// program (Ctrl+S not left to the browser); a file opened by the file input and one dropped onto
// the editor are in the editor, named so in the menu and the diagnostics; New and a paste over the
// whole text give untitled.nc, never the last program's name; a reload keeps the text, the program's
// entry, the machine and the Settings; a server file's edits kept per file across another program
// chosen and a reload, marked in the menu and the title, kept by Save, dropped by Revert (asked
// first), and no edit once typed back to the file's text. The Settings against the command line run in the test:
// --set "#100=2" completing examples/alarm.nc, --param 6050=102 and --lib macros making G102 of
// examples/custom-cycle.nc call O9010 (and without the folder the CLI's alarm), a bad --set and
// --param refused beside their fields in the CLI's words, a tool offset edited moving the G41 D1
// contour by the new radius (worked out by hand), offset memory A's value named H length and D
// radius in the header, NC2071 shown in the CLI's words with a button to the Settings' offsets. Generate: each curve's fields, defaults and units
// against `ncurve gen --list`, gen's default form and tolerance, an expression's NAME=VALUE
// parameters, gen asked with the Settings' parameters. A 40 x 30 rectangle clockwise under G41 D1 of
// radius 5: the tool centre's sides on X-5..45, Y-5..35, the programmed contour drawn dashed through
// the program's corners (hidden and shown by its legend's box), the debugger's tool (T1, D1 radius 5,
// G41) and the cutter's circle of radius 5 about the last point; a watch checked with the Settings;
// the tab open kept across a reload. Screenshots of the Settings tab and of the debugger on the
// rectangle at 1024 x 768 and 1920 x 1080 (workbench-settings-*.png, workbench-tool-*.png), the
// Settings, the tabs' names on one line, and a lathe's offsets within the panel at 1024.
'use strict';
const {execFileSync, spawnSync} = require('child_process');
const fs = require('fs');
const path = require('path');
const {browser, checker, launch, serve, newPage, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

const example = (n) => path.join(src, 'examples', n);
const macros = path.join(src, 'macros');
// `ncurve run FILE ARGS --json`: its summary (exit 1 on an alarm is an answer too)
const cli = (file, args) => JSON.parse(spawnSync(ncurve, ['run', file, ...args, '--json'], {encoding: 'utf8'}).stdout);
const cliError = (file, args) => spawnSync(ncurve, ['run', file, ...args], {encoding: 'utf8'}).stderr.trim();
// `ncurve gen --list`: each curve with its parameters' defaults and units ("(doc, mm)")
function genList() {
  const text = execFileSync(ncurve, ['gen', '--list'], {encoding: 'utf8'});
  const curves = [];
  for (const line of text.split('\n')) {
    let m = /^ {2}(\S+) +\S/.exec(line);
    if (m && m[1] !== 'expr') { curves.push({name: m[1], params: []}); continue; }
    m = /^ {2} +--(\S+) (\S+) {2}\((.*)\)$/.exec(line);
    if (m && curves.length && m[1] !== 'from') {
      const unit = /(?:^|, )(mm)$/.exec(m[3]);
      curves[curves.length - 1].params.push({name: m[1], value: Number(m[2]), unit: unit ? unit[1] : ''});
    }
  }
  return curves;
}

(async () => {
  const listed = genList();
  const genDefault = JSON.parse(execFileSync(ncurve, ['gen', 'ellipse', '--json'], {encoding: 'utf8'}));
  const {server, port} = await serve(ncurve, [example('spiral.nc'), example('alarm.nc'), example('custom-cycle.nc'),
    '--lib', macros]);
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  await finish({check, counts, out}, async () => {
    const {page, errors: all} = await newPage(context);
    const errors = {get length() { return this.list().length; }, list: () => all.filter((e) => !/status of 400/.test(e)),
      join: (sep) => errors.list().join(sep)};  // the refusals asked for
    const url = `http://127.0.0.1:${port}/`;
    await page.goto(url);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1);
    const runs = () => page.evaluate(() => ncurveWorkbench.runs);
    const ran = (n) => page.waitForFunction((k) => ncurveWorkbench.runs > k && ncurveWorkbench.settled(), n);
    const text = (id) => page.evaluate((i) => document.getElementById(i).textContent, id);
    const W = () => page.evaluate(() => ({text: ncurveWorkbench.editor.text, name: ncurveWorkbench.name,
      menu: document.getElementById('file').selectedOptions[0].text, machine: document.getElementById('machine').value,
      diags: ncurveWorkbench.diagnostics.map((d) => d.file), where: [...document.querySelectorAll('#diags .where')].map((e) => e.textContent),
      summary: ncurveWorkbench.summary, note: document.getElementById('settings-note').textContent}));
    // the editor's text set as typing it would (an input event: the page runs it)
    const typeAll = async (t) => {
      const n = await runs();
      await page.evaluate((v) => {
        const i = ncurveWorkbench.editor.input;
        i.focus();
        i.select();
        document.execCommand('insertText', false, v);
      }, t);
      await ran(n);
    };
    // the page's program chosen in its menu, run
    const choose = async (name) => {
      const n = await runs();
      await page.selectOption('#file', name);
      await ran(n);
      await page.waitForFunction((m) => ncurveWorkbench.name === m && ncurveWorkbench.settled(), name);
    };

    // ---- save: the editor's bytes, named as the program ----
    let w = await W();
    check(w.name === 'spiral.nc' && w.text === fs.readFileSync(example('spiral.nc'), 'utf8'), `spiral.nc opened (${w.name})`);
    let [dl] = await Promise.all([page.waitForEvent('download'), page.click('#save')]);
    let bytes = fs.readFileSync(await dl.path(), 'utf8');
    check(dl.suggestedFilename() === 'spiral.nc' && bytes === w.text, `Save: spiral.nc, ${bytes.length} bytes, the editor's text`);
    // Ctrl+S in the editor after an edit: the edited text, the browser's own save not done
    await page.evaluate(() => {
      window.ctrlS = [];
      window.addEventListener('keydown', (e) => { if (e.ctrlKey && e.key === 's') window.ctrlS.push(e.defaultPrevented); });
    });
    let n = await runs();
    await page.evaluate(() => {
      const t = ncurveWorkbench.editor.input;
      t.focus();
      t.setSelectionRange(t.value.length, t.value.length);
    });
    await page.keyboard.type('(EDITED)\n');
    await ran(n);
    w = await W();
    [dl] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('Control+s')]);
    bytes = fs.readFileSync(await dl.path(), 'utf8');
    const prevented = await page.evaluate(() => window.ctrlS);
    check(dl.suggestedFilename() === 'spiral.nc' && bytes === w.text && bytes.endsWith('(EDITED)\n'),
          `Ctrl+S: spiral.nc, the edited text (${bytes.length} bytes)`);
    check(prevented.length === 1 && prevented[0] === true, `Ctrl+S kept from the browser (default prevented: ${prevented})`);
    check(w.menu === 'spiral.nc (edited)', `edited, saved as a download: still marked (${w.menu})`);

    // ---- open a file of this computer: by the file input, by a drop onto the editor ----
    const mine = 'G90 G01 X10. F100.\n#1=[1+\nM30\n';
    n = await runs();
    await page.setInputFiles('#open-file', {name: 'mine.nc', mimeType: 'text/plain', buffer: Buffer.from(mine)});
    await ran(n);
    w = await W();
    check(w.text === mine && w.name === 'mine.nc' && w.menu === 'mine.nc (opened)', `opened: its text, "${w.menu}" in the menu`);
    check(w.diags.length > 0 && w.diags.every((f) => f === 'mine.nc') && w.where.every((x) => x.startsWith('mine.nc:2:')),
          `its diagnostics name it (${w.where.join(' ')})`);
    n = await runs();
    const dropped = 'G90 G00 X5. Y5.\nM30\n';
    await page.evaluate((t) => {
      const dt = new DataTransfer();
      dt.items.add(new File([t], 'dropped.nc', {type: 'text/plain'}));
      const target = ncurveWorkbench.editor.input;
      for (const type of ['dragenter', 'dragover', 'drop'])
        target.dispatchEvent(new DragEvent(type, {dataTransfer: dt, bubbles: true, cancelable: true}));
    }, dropped);
    await ran(n);
    w = await W();
    check(w.text === dropped && w.name === 'dropped.nc' && w.menu === 'dropped.nc (opened)', `dropped onto the editor: "${w.menu}"`);

    // ---- new, and a paste over a whole program: untitled.nc ----
    await choose('spiral.nc');
    n = await runs();
    await page.click('#new');
    await ran(n);
    w = await W();
    check(w.text === '' && w.name === 'untitled.nc' && w.menu === 'untitled.nc (new)' && w.summary.none,
          `New: an empty untitled.nc ("${w.menu}")`);
    await typeAll('G01 X1. F100.\n#2=[2*\nM30\n');
    w = await W();
    check(w.where.length > 0 && w.where.every((x) => x.startsWith('untitled.nc:2:')), `the new program's diagnostics: ${w.where.join(' ')}`);
    await choose('spiral.nc');
    n = await runs();
    await page.evaluate(() => {  // select all, paste (the paste event, then the text as the browser inserts it)
      const i = ncurveWorkbench.editor.input, dt = new DataTransfer(), t = 'G00 X0 Y0\n#3=[3/\nM30\n';
      dt.setData('text/plain', t);
      i.focus();
      i.select();
      i.dispatchEvent(new ClipboardEvent('paste', {clipboardData: dt, bubbles: true, cancelable: true}));
      document.execCommand('insertText', false, t);
    });
    await ran(n);
    w = await W();
    check(w.name === 'untitled.nc' && w.menu === 'untitled.nc (pasted)' && w.diags.length > 0 && w.diags.every((f) => f === 'untitled.nc') &&
          !w.where.some((x) => x.startsWith('spiral.nc')), `pasted over spiral.nc: named untitled.nc (${w.where.join(' ')})`);

    // ---- a reload keeps the program, its menu entry, the machine and the settings ----
    n = await runs();
    await page.selectOption('#machine', 'fanuc-mill');
    await ran(n);
    await page.click('button[data-tab="settings"]');
    await page.fill('#set-vars', '#100=7');
    await page.locator('#set-vars').dispatchEvent('change');
    await page.waitForFunction(() => ncurveWorkbench.settled() && /#100=7/.test(document.getElementById('settings-note').textContent));
    const before = await W();
    await page.reload();
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    w = await W();
    const setKept = await page.inputValue('#set-vars');
    check(w.text === before.text && w.name === 'untitled.nc' && w.menu === 'untitled.nc (pasted)' && w.machine === 'fanuc-mill' &&
          w.summary.machine === before.summary.machine && setKept === '#100=7',
          `reloaded: the text, "${w.menu}", machine ${w.machine} (${w.summary.machine}), --set ${setKept}`);
    check(w.where.every((x) => x.startsWith('untitled.nc:')) && w.where.length > 0, 'reloaded: its diagnostics name it');
    const tabKept = await page.evaluate(() => !document.getElementById('tab-settings').hidden &&
      document.querySelector('.wb-tabs button.on').dataset.tab);
    check(tabKept === 'settings', `reloaded: the Settings tab still open (${tabKept})`);
    // an edited server file comes back as its own entry with the edit
    await choose('spiral.nc');
    await typeAll('G00 X1. Y2.\nM30\n');
    await page.reload();
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    w = await W();
    check(w.text === 'G00 X1. Y2.\nM30\n' && w.menu === 'spiral.nc (edited)' && w.name === 'spiral.nc', `reloaded: spiral.nc as edited (${w.menu})`);

    // ---- a server file's edits kept per file: another program and back, a reload, Save, Revert ----
    const disk = (f) => fs.readFileSync(example(f), 'utf8');
    const marks = () => page.evaluate(() => ({title: document.title, revert: !document.getElementById('revert').disabled,
      entries: [...document.getElementById('file').options].map((o) => o.text)}));
    let m = await marks();
    check(m.title.startsWith('\u25cf spiral.nc (edited)') && m.revert, `the edit marked in the title and Revert offered: "${m.title}"`);
    await choose('alarm.nc');
    w = await W();
    m = await marks();
    check(w.text === disk('alarm.nc') && w.menu === 'alarm.nc' && !m.title.startsWith('\u25cf') && !m.revert &&
          m.entries.includes('spiral.nc (edited)'), `alarm.nc from disk, unmarked; the menu: ${m.entries.join(', ')}`);
    await choose('spiral.nc');
    w = await W();
    check(w.text === 'G00 X1. Y2.\nM30\n' && w.menu === 'spiral.nc (edited)', `spiral.nc chosen again: the edit is there (${w.menu})`);
    // alarm.nc edited too, the page reloaded on it: each file's edit under its own entry
    await choose('alarm.nc');
    await typeAll(disk('alarm.nc') + '(MINE)\n');
    await page.reload();
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1 && ncurveWorkbench.settled());
    w = await W();
    m = await marks();
    check(w.text === disk('alarm.nc') + '(MINE)\n' && w.menu === 'alarm.nc (edited)' && m.entries.includes('spiral.nc (edited)'),
          `reloaded on alarm.nc: its edit, and spiral.nc's kept (${m.entries.join(', ')})`);
    await choose('spiral.nc');
    check((await W()).text === 'G00 X1. Y2.\nM30\n', 'and spiral.nc chosen after the reload: its edit');
    // Save downloads a copy and leaves the server's file as it is: the mark stays
    [dl] = await Promise.all([page.waitForEvent('download'), page.click('#save')]);
    check(fs.readFileSync(await dl.path(), 'utf8') === 'G00 X1. Y2.\nM30\n' && (await W()).menu === 'spiral.nc (edited)',
          'Save: the edited text downloaded, still marked edited');
    // Revert asks first: refused, nothing changes; accepted, the file as on disk and no mark
    page.once('dialog', (d) => d.dismiss());
    await page.click('#revert');
    await page.waitForTimeout(300);
    check((await W()).text === 'G00 X1. Y2.\nM30\n', 'Revert refused at its question: the edit stays');
    page.once('dialog', (d) => d.accept());
    n = await runs();
    await page.click('#revert');
    await ran(n);
    w = await W();
    m = await marks();
    check(w.text === disk('spiral.nc') && w.menu === 'spiral.nc' && !m.revert && !m.title.startsWith('\u25cf') &&
          m.entries.includes('alarm.nc (edited)'), `Revert: spiral.nc as on disk, unmarked (${m.entries.join(', ')})`);
    // an edit typed back to the file's text is no edit
    await choose('alarm.nc');
    await typeAll(disk('alarm.nc'));
    check((await W()).menu === 'alarm.nc' && !(await marks()).revert, 'alarm.nc typed back to its file: unmarked');
    n = await runs();
    await page.selectOption('#machine', '');
    await ran(n);

    // ---- the Settings against the command line ----
    const setting = async (id, value) => {
      // (a run an earlier change started, or one still in its 300 ms wait, ends first)
      await page.waitForFunction(() => ncurveWorkbench.settled());
      await page.waitForTimeout(400);
      await page.waitForFunction(() => ncurveWorkbench.settled());
      const k = await page.evaluate(() => [ncurveWorkbench.runs, ncurveWorkbench.refusals]);
      await page.fill(id, value);
      await page.locator(id).dispatchEvent('change');
      // a run shown, or refused (400)
      await page.waitForFunction(([r, f]) => (ncurveWorkbench.runs > r && ncurveWorkbench.settled()) || ncurveWorkbench.refusals > f, k);
    };
    await page.click('button[data-tab="settings"]');
    await setting('#set-vars', '');
    await choose('alarm.nc');
    const alarmed = cli(example('alarm.nc'), []), completed = cli(example('alarm.nc'), ['--set', '#100=2']);
    w = await W();
    check(!w.summary.ok && w.summary.alarm.code === alarmed.alarm.code, `alarm.nc without --set: ${w.summary.alarm && w.summary.alarm.code} (CLI ${alarmed.alarm.code})`);
    await setting('#set-vars', '#100=2');
    w = await W();
    const moves = (s) => JSON.stringify([s.motions, s.moves, s.extent, s.feed_length_mm, s.rapid_length_mm]);
    check(w.summary.ok && completed.ok && moves(w.summary) === moves(completed),
          `--set "#100=2": completed as the CLI (${w.summary.motions} motions, extents ${JSON.stringify(w.summary.extent)})`);
    check(w.note.includes('--set "#100=2"'), `in force, in the header: ${w.note}`);
    // a bad variable, a bad parameter: the CLI's message beside the field
    await setting('#set-vars', '#abc=1');
    let why = await text('set-vars-why');
    const cliSet = cliError(example('alarm.nc'), ['--set', '#abc=1']);
    check(why === "--set: '#abc=1' is not of the form #100=5" && cliSet.endsWith(why), `#abc=1 refused beside the field: "${why}" (CLI: ${cliSet})`);
    check(await page.getAttribute('#set-vars', 'aria-invalid') === 'true' && /400/.test(await text('status')), 'the field marked, the status says 400');
    await setting('#set-vars', '#100=2');
    await setting('#set-param', 'abc');
    why = await text('set-param-why');
    const cliParam = cliError(example('alarm.nc'), ['--param', 'abc']);
    check(why === "--param: 'abc' is not of the form 6050=102" && cliParam.endsWith(why), `a bad parameter refused beside the field: "${why}" (status: ${await text('status')})`);
    await setting('#set-param', '6050=x1');
    why = await text('set-param-why');
    check(cliError(example('alarm.nc'), ['--param', '6050=x1']).endsWith(why) && why.includes('6050=x1'), `6050=x1: "${why}"`);
    await page.screenshot({path: path.join(out, 'workbench-settings-refused.png')});
    await setting('#set-param', '');
    check(await text('set-param-why') === '' && (await W()).summary.ok, 'cleared: the message gone, the run made');

    // --param 6050=102 and --lib macros: G102 calls O9010
    await choose('custom-cycle.nc');
    const cc = example('custom-cycle.nc');
    const noParam = cli(cc, ['--lib', macros]), both = cli(cc, ['--lib', macros, '--param', '6050=102']);
    const noLib = cli(cc, ['--param', '6050=102']);
    w = await W();
    check(!w.summary.ok && w.summary.alarm.code === noParam.alarm.code, `custom-cycle.nc with the folder, no parameter: ${w.summary.alarm.code} (CLI ${noParam.alarm.code})`);
    await setting('#set-param', '6050=102');
    w = await W();
    check(w.summary.ok && both.ok && moves(w.summary) === moves(both), `--param 6050=102 --lib macros: completed as the CLI (${w.summary.motions} motions, ${w.summary.moves.line} lines)`);
    const libBox = `#set-libs input[value="${macros}"]`;
    n = await runs();
    await page.uncheck(libBox);
    await ran(n);
    w = await W();
    check(!w.summary.ok && w.summary.alarm.code === noLib.alarm.code && w.summary.alarm.message === noLib.alarm.message,
          `the folder unticked: ${w.summary.alarm.code} ${w.summary.alarm.message} (CLI without --lib: ${noLib.alarm.code})`);
    n = await runs();
    await page.check(libBox);
    await ran(n);
    w = await W();
    check(w.summary.ok && moves(w.summary) === moves(both) && w.note.includes(`--lib ${macros}`) && w.note.includes('--param 6050=102'),
          `ticked again: completed as the CLI with --lib (${w.note})`);
    // 3401#0 = 1: X10 is 10 mm, as the CLI's --param
    const dp = path.join(out, 'decimal-point.nc');
    fs.writeFileSync(dp, 'G90 G01 X10 Y5 F100\nM30\n');
    await setting('#set-param', '3401#0=1');
    await typeAll('G90 G01 X10 Y5 F100\nM30\n');
    const dpCli = cli(dp, ['--param', '3401#0=1']), dpPlain = cli(dp, []);
    const feedEnd = () => page.evaluate(() => {  // the end of the first move at feed
      const B = ncurveWorkbench.plot.moves;
      for (let i = 0; i < B.count; i++) if (B.kind[i] !== 0) return [B.end[3 * i], B.end[3 * i + 1]];
      return null;
    });
    w = await W();
    const dpEnd = await feedEnd();
    check(w.summary.ok && JSON.stringify(w.summary.extent) === JSON.stringify(dpCli.extent) &&
          JSON.stringify(dpCli.extent) !== JSON.stringify(dpPlain.extent) && JSON.stringify(dpEnd) === '[10,5]',
          `--param 3401#0=1: X10 Y5 are 10 and 5 mm (the line ends at ${JSON.stringify(dpEnd)}), extents as the CLI's ${JSON.stringify(dpCli.extent)}`);
    await setting('#set-param', '');
    await setting('#set-vars', '');

    // ---- a tool offset edited: the G41 D1 contour moved by the new radius ----
    // a 40 x 20 rectangle counter-clockwise from (0, 0), G41 (left: inside): radius r puts the bottom
    // side's end (line 4) at (40 - r, r) and the top's (line 6) at (r, 20 - r)
    await page.click('#new');
    await typeAll('G90 G17 G21 G54 G00 X-10. Y-10. Z5.\nG01 Z-1. F200.\nG41 D1 G01 X0 Y0 F500.\nX40.\nY20.\nX0\nY0\nG40 G01 X-10. Y-10.\nG00 Z5.\nM30\n');
    const endOf = (line) => page.evaluate((l) => {
      const B = ncurveWorkbench.plot.moves;
      let at = null;
      for (let i = 0; i < B.count; i++) if (B.line[i] === l) at = [B.end[3 * i], B.end[3 * i + 1]];
      return at;
    }, line);
    check(JSON.stringify(await endOf(4)) === '[40,0]', `no offset on the factory mill: the bottom ends at ${JSON.stringify(await endOf(4))}`);
    await page.fill('#set-offset-new', '1');
    n = await runs();
    await page.click('#set-offset-add');
    await ran(n);
    for (const r of [5, 3]) {
      await setting('#set-offsets tr[data-offset="1"] input[data-field="length"]', String(r));
      await page.waitForFunction((r) => {  // the run with this radius drawn (a slow machine's runs overlap)
        const B = ncurveWorkbench.plot.moves;
        for (let i = B.count - 1; i >= 0; i--) if (B.line[i] === 4) return Math.abs(B.end[3 * i] - (40 - r)) < 1e-9;
        return false;
      }, r, {timeout: 30000}).catch(() => {});
      const [b, t] = [await endOf(4), await endOf(6)];
      check(Math.abs(b[0] - (40 - r)) < 1e-9 && Math.abs(b[1] - r) < 1e-9 && Math.abs(t[0] - r) < 1e-9 && Math.abs(t[1] - (20 - r)) < 1e-9,
            `D1 = ${r}: the bottom ends at ${JSON.stringify(b)}, the top at ${JSON.stringify(t)} (by hand ${40 - r},${r} and ${r},${20 - r})`);
    }
    w = await W();
    // offset memory A: the one value of No.1 is the D radius this contour is cut by, and the H length
    check(/tool offsets: No\.1 3 \(H length and D radius\)/.test(w.note), `the offset in force, in the header: ${w.note}`);
    // NC2071, a D the profile does not hold: the command line's message as it is, and beside it the
    // page's way to the offsets, which opens the Settings tab
    const noOffset = 'G90 G17 G00 X0 Y0 Z5.\nG01 Z-1. F100.\nG41 D7 G01 X10. Y0\nX20.\nG40 G00 X30.\nM30\n';
    fs.writeFileSync(path.join(out, 'no-offset.nc'), noOffset);
    const cliWarning = cli(path.join(out, 'no-offset.nc'), []).warnings.find((x) => x.code === 'NC2071');
    await typeAll(noOffset);
    await page.click('button[data-tab="summary"]');
    const row = await page.evaluate(() => {
      const li = [...document.querySelectorAll('#diags li')].find((l) => l.querySelector('strong').textContent === 'NC2071');
      return li ? {text: li.textContent, go: li.querySelector('button') ? li.querySelector('button').textContent : ''} : null;
    });
    check(cliWarning && row && row.text.includes(' ' + cliWarning.message + ' ') && row.go === 'Settings: Tool offsets',
          `NC2071: the CLI's message and the page's pointer (${row && row.text})`);
    await page.click('#diags li button');
    check(await page.evaluate(() => !document.getElementById('tab-settings').hidden), 'its pointer opens the Settings tab');

    // ---- the programmed contour and the tool at the step: a 40 x 30 rectangle clockwise under G41 D1,
    // radius 5 (the cutter on the left of its way: outside, its centre on X-5..45, Y-5..35; the last
    // side, before G40, ends square to its end) ----
    await setting('#set-offsets tr[data-offset="1"] input[data-field="length"]', '5');
    await typeAll('T1 M06\nG90 G17 G21 G54 G00 G43 H1 X-20. Y-20. Z5.\nG01 Z-1. F200.\nG41 D1 G01 X0 Y0 F500.\nY30.\nX40.\nY0\nX0\n' +
                  'G40 G01 X-20. Y-20.\nG00 Z5.\nM30\n');
    const tool = [[-5, 35], [45, 35], [45, -5], [0, -5]], sides = [];
    for (let side = 0; side < 4; side++) sides.push(await endOf(5 + side));
    check(sides.every((e, k) => e && Math.abs(e[0] - tool[k][0]) < 1e-6 && Math.abs(e[1] - tool[k][1]) < 1e-6),
          `the tool centre's sides end at ${JSON.stringify(sides)} (by hand ${JSON.stringify(tool)})`);
    const drawn = await page.evaluate(() => ({state: ncurveWorkbench.plot.state().programmed, points: ncurveWorkbench.plot.programmedPoints(),
      legend: document.querySelector('#legend .wb-programmed') && document.querySelector('#legend .wb-programmed').textContent}));
    const pts = [];
    for (let v = 0; v < drawn.points.length; v += 3) pts.push(drawn.points.slice(v, v + 3));
    const near = (p, x, y) => Math.abs(p[0] - x) < 1e-4 && Math.abs(p[1] - y) < 1e-4;
    // every point on the rectangle's sides, or on the way in and out along X = Y from (-20, -20)
    const onContour = (p) => ((Math.abs(p[0]) < 1e-4 || Math.abs(p[0] - 40) < 1e-4) && p[1] > -1e-4 && p[1] < 30 + 1e-4) ||
      ((Math.abs(p[1]) < 1e-4 || Math.abs(p[1] - 30) < 1e-4) && p[0] > -1e-4 && p[0] < 40 + 1e-4) ||
      (Math.abs(p[0] - p[1]) < 1e-4 && p[0] > -20 - 1e-4 && p[0] < 1e-4);
    check(drawn.state && drawn.state.moves === 6 && drawn.state.visible && pts.length === 12 &&
          [[0, 0], [0, 30], [40, 30], [40, 0], [-20, -20]].every(([x, y]) => pts.some((p) => near(p, x, y))) &&
          pts.every(onContour) && pts.every((p) => Math.abs(p[2] + 1) < 1e-4) && /programmed 6/.test(drawn.legend || ''),
          `the programmed contour dashed: ${drawn.state && drawn.state.moves} moves through the rectangle's corners at Z-1 ` +
          `(${pts.map((p) => p.slice(0, 2).map((v) => +v.toFixed(3)).join(',')).join(' ')}); legend "${drawn.legend}"`);
    await page.click('#legend .wb-programmed input');
    const hidden = await page.evaluate(() => ncurveWorkbench.plot.state().programmed.visible);
    await page.click('#legend .wb-programmed input');
    const again = await page.evaluate(() => ncurveWorkbench.plot.state().programmed.visible);
    check(hidden === false && again === true, `its box hides it and shows it again (${hidden}, ${again})`);
    // the debugger: after Y30. (block 5: X40. next) T1, D1 of radius 5 under G41 and H1 of length 5
    // (offset memory A: one value for H and D) under G43; at the end the
    // cutter's circle about the last point, X-20 Y-20 Z5, of radius 5
    await page.click('button[data-tab="debug"]');
    await page.waitForFunction(() => ncurveWorkbench.trace && ncurveWorkbench.settled());
    await page.evaluate(() => ncurveWorkbench.goTo(5));
    const atStep = await page.evaluate(() => ({line: ncurveWorkbench.state.line, text: document.getElementById('dbg-tool').innerText,
      cutter: ncurveWorkbench.plot.state().cutter}));
    check(atStep.line === 6 && /T1\b/.test(atStep.text) && /D1 radius 5 mm \(G41\)/.test(atStep.text) &&
          /H1 length 5 mm \(G43\)/.test(atStep.text) && atStep.cutter && atStep.cutter.radius === 5,
          `block 5 (line ${atStep.line}): the tool "${atStep.text.replace(/\n/g, ' · ')}", a cutter of radius ${atStep.cutter && atStep.cutter.radius} drawn`);
    await page.evaluate(() => ncurveWorkbench.goTo(Infinity));
    const circle = await page.evaluate(() => ncurveWorkbench.plot.cutterPoints());
    let ring = circle.length >= 3 * 32;
    for (let v = 0; v < circle.length; v += 3)
      ring = ring && Math.abs(Math.hypot(circle[v] + 20, circle[v + 1] + 20) - 5) < 1e-6 && Math.abs(circle[v + 2] - 5) < 1e-9;
    check(ring, `after the last block: the cutter's circle, ${circle.length / 3} points, 5 mm from X-20 Y-20 at Z5`);
    await page.evaluate(() => ncurveWorkbench.goTo(5));
    for (const [size, file] of [[{width: 1024, height: 768}, 'workbench-tool-1024.png'], [{width: 1920, height: 1080}, 'workbench-tool-1920.png']]) {
      await page.setViewportSize(size);
      await page.waitForTimeout(300);
      const fit = await page.evaluate(() => {
        const t = document.getElementById('dbg-tool').getBoundingClientRect(), p = document.getElementById('tab-debug').getBoundingClientRect();
        const legend = document.getElementById('legend').getBoundingClientRect(), plot = document.getElementById('plot').getBoundingClientRect();
        return t.width > 0 && t.left >= p.left && t.right <= p.right + 1 && t.right <= innerWidth && legend.right <= plot.right + 1 && legend.bottom <= plot.bottom + 1;
      });
      check(fit, `${size.width} x ${size.height}: the tool in the debugger's panel, the legend inside the plot`);
      await page.screenshot({path: path.join(out, file)});
    }
    await page.setViewportSize({width: 1400, height: 860});
    // a watch is checked with the Settings: a bad --set refuses it in the --set's words
    await page.click('button[data-tab="settings"]');
    await setting('#set-vars', '#abc=1');
    await page.click('button[data-tab="debug"]');
    await page.fill('#watch-var', '#100');
    await page.click('#watch-add');
    await page.waitForFunction(() => document.getElementById('watch-why').textContent !== '');
    const watchWhy = await text('watch-why'), sent = await page.evaluate(() => ncurveWorkbench.watchRequest);
    check(watchWhy === "--set: '#abc=1' is not of the form #100=5" && sent.tool_offsets && sent.tool_offsets['1'].length === 5 &&
          Array.isArray(sent.lib) && sent.max_steps === undefined,
          `a watch asked with the Settings: "${watchWhy}", sent ${JSON.stringify(sent)}`);
    await page.click('button[data-tab="settings"]');
    await setting('#set-vars', '');
    await setting('#set-offsets tr[data-offset="1"] input[data-field="length"]', '3');
    await setting('#set-offsets tr[data-offset="1"] input[data-field="length"]', 'abc');
    await page.waitForFunction(() => document.getElementById('set-offsets-why').textContent !== '', null,
                               {timeout: 30000}).catch(() => {});
    why = await text('set-offsets-why');
    check(why === "\"tool_offsets\": offset 1: 'length' must be a number (mm)", `a bad offset refused beside the table: ${why}`);
    await setting('#set-offsets tr[data-offset="1"] input[data-field="length"]', '3');
    // fanuc-mill's own offset 1 (100) shown
    n = await runs();
    await page.selectOption('#machine', 'fanuc-mill');
    await ran(n);
    const shown = await page.inputValue('#set-offsets tr[data-offset="1"] input[data-field="length"]');
    check(shown === '100', `fanuc-mill: its offset 1 shown as its profile gives it (${shown}); the edit kept for the factory mill`);
    // the Settings inside their panel, and each tab's name on one line (the open tab's in bold too)
    const fits = () => page.evaluate(() => {
      const p = document.getElementById('tab-settings'), r = p.getBoundingClientRect();
      const inside = [...p.querySelectorAll('textarea, input, button, label')].every((e) => {
        const b = e.getBoundingClientRect();
        return b.width === 0 || (b.left >= r.left - 1 && b.right <= r.right + 1);
      });
      const bar = document.querySelector('.wb-bar').getBoundingClientRect();
      const tabs = [...document.querySelectorAll('.wb-tabs button')].map((b) => b.getBoundingClientRect().height);
      return {inside, across: p.scrollWidth <= p.clientWidth + 1, bar: bar.height, width: innerWidth,
        tabs: tabs.every((h) => h === tabs[0]) && tabs[0] < 36 ? 'one line' : tabs.join(' ')};
    });
    for (const [size, file] of [[{width: 1024, height: 768}, 'workbench-settings-1024.png'], [{width: 1920, height: 1080}, 'workbench-settings-1920.png']]) {
      await page.setViewportSize(size);
      await page.waitForTimeout(300);
      const fit = await fits();
      check(fit.inside && fit.across && fit.bar < 100 && fit.tabs === 'one line',
            `${size.width} x ${size.height}: the Settings within the panel, the header ${fit.bar} px tall, the tabs' names on ${fit.tabs}`);
      await page.screenshot({path: path.join(out, file)});
    }
    // a lathe's seven offset columns, one edited (its "profile's" button beside), within the panel at 1024
    await page.setViewportSize({width: 1024, height: 768});
    n = await runs();
    await page.selectOption('#machine', 'fanuc-lathe');
    await ran(n);
    await setting('#set-offsets tr[data-offset="1"] input[data-field="x_wear"]', '0.02');
    let fit = await fits();
    check(fit.inside && fit.across && fit.tabs === 'one line', `1024 x 768: a lathe's offsets within the panel (${fit.inside}, ${fit.across})`);
    await page.screenshot({path: path.join(out, 'workbench-settings-lathe-1024.png')});
    n = await runs();
    await page.click('#set-offsets-reset');
    await ran(n);
    await page.setViewportSize({width: 1400, height: 860});
    n = await runs();
    await page.selectOption('#machine', '');
    await ran(n);
    await page.click('#set-offsets-reset');

    // ---- Generate: a field for each parameter, gen's defaults ----
    await page.click('button[data-tab="gen"]');
    const form = await page.inputValue('#gen-form'), tol = await page.inputValue('#gen-tol');
    check(form === genDefault.form && Number(tol) === genDefault.tolerance, `gen's default form ${form} and tolerance ${tol} (gen: ${genDefault.form}, ${genDefault.tolerance})`);
    for (const c of listed) {
      await page.selectOption('#gen-curve', c.name);
      const fields = await page.evaluate(() => [...document.querySelectorAll('#gen-fields label')].map((l) => ({
        name: l.querySelector('.name').textContent, value: Number(l.querySelector('input').value), unit: l.querySelector('.unit').textContent,
        visible: l.getBoundingClientRect().width > 0})));
      const same = fields.length === c.params.length && fields.every((f, k) => f.name === c.params[k].name && f.visible &&
        Math.abs(f.value - c.params[k].value) <= 1e-9 * Math.max(1, Math.abs(c.params[k].value)) && f.unit === c.params[k].unit);
      check(same, `${c.name}: ${fields.map((f) => `${f.name} ${f.value} ${f.unit}`).join(', ') || 'no parameters'} (gen --list: ${c.params.map((p) => `${p.name} ${p.value} ${p.unit}`).join(', ')})`);
    }
    // gen asked with the Settings' parameters: a bad one refused by /api/gen in --param's words
    await page.click('button[data-tab="settings"]');
    await setting('#set-param', '3410=x');
    await page.click('button[data-tab="gen"]');
    await page.selectOption('#gen-curve', 'ellipse');
    await page.click('#gen');
    await page.waitForFunction(() => document.getElementById('gen-error').textContent !== '');
    why = await text('gen-error');
    check(why === "400: --param: '3410=x' is not of the form 6050=102", `gen with the Settings' --param 3410=x: ${why}`);
    await page.click('button[data-tab="settings"]');
    await setting('#set-param', '');
    await page.click('button[data-tab="gen"]');
    // an ellipse's a and b typed in the fields, generated: its extents are the new semi-axes
    await page.selectOption('#gen-curve', 'ellipse');
    await page.fill('#gen-fields input[data-param="a"]', '50');
    await page.fill('#gen-fields input[data-param="b"]', '10');
    // (the run the cleared setting started, or one still in its 300 ms wait, ends first)
    await page.waitForFunction(() => ncurveWorkbench.settled());
    await page.waitForTimeout(400);
    await page.waitForFunction(() => ncurveWorkbench.settled());
    n = await runs();
    await page.click('#gen');
    await ran(n);
    // the largest |X| and |Y| the moves at feed reach
    const reach = () => page.evaluate(() => {
      const B = ncurveWorkbench.plot.moves;
      let x = 0, y = 0;
      for (let i = 0; i < B.count; i++) if (B.kind[i] !== 0) x = Math.max(x, Math.abs(B.end[3 * i])), y = Math.max(y, Math.abs(B.end[3 * i + 1]));
      return [x, y];
    });
    w = await W();
    let [rx, ry] = await reach();
    check(w.summary.ok && Math.abs(rx - 50) < 0.01 && Math.abs(ry - 10) < 0.01 && w.name === 'generated.nc',
          `ellipse a=50 b=10 from the fields: the cut reaches X ${rx}, Y ${ry}`);
    // an expression's parameters as NAME=VALUE
    await page.selectOption('#gen-curve', 'expr');
    await page.fill('#gen-x', 'a*COS[t]');
    await page.fill('#gen-y', 'b*SIN[t]');
    await page.fill('#gen-params', 'a=50, b=10');
    n = await runs();
    await page.click('#gen');
    await ran(n);
    w = await W();
    [rx, ry] = await reach();
    check(await text('gen-error') === '' && w.summary.ok && /EXPR|A\*COS|\bA\b/i.test(w.text) && Math.abs(rx - 50) < 0.01 && Math.abs(ry - 10) < 0.01,
          `an expression with a=50, b=10: generated (${await text('gen-error')}), the cut reaches X ${rx}, Y ${ry}`);
    await page.fill('#gen-params', 'a=50, b=x');
    await page.click('#gen');
    why = await text('gen-error');
    check(/"b=x" is not NAME=VALUE/.test(why), `a bad parameter refused: ${why}`);
    await page.setViewportSize({width: 1024, height: 768});
    await page.selectOption('#gen-curve', 'trochoid');
    await page.screenshot({path: path.join(out, 'workbench-gen-fields-1024.png')});
    check(errors.length === 0, `no script errors (${errors.join('; ')})`);
  }, async () => {
    await close();
    server.kill();
  });
})();
