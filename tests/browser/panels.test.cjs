// The workbench's Generate panel and machine file in a real browser: headless Chromium (Debian's), playwright-core.
//   node panels.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Starts `ncurve serve --port 0 examples/spiral.nc` and checks: the Curve list holds the curves
// `ncurve gen --list` prints, choosing each fills its parameters with the defaults it prints; an
// expression x = 10 cos t, y = 10 sin t, t 0..360 (degrees, as gen's macro language) generates a
// program whose moves at feed all lie within 10 ± tol of the origin and go once around; a bad
// expression's error is shown beside the button; gen's other forms (macro, adaptive macro, cycle)
// run as generated, named generated.nc; gen's warnings shown; profiles/fanuc-lathe.toml chosen as a file runs
// the page as a lathe (ZX view) and generates a lathe curve on it; a broken profile shows the
// server's 400 in the status line. Screenshots workbench-gen-expr.png, workbench-machine-file.png
// in OUT_DIR. Exit 77 (skipped) where no Chromium is installed.
'use strict';
const {execFileSync} = require('child_process');
const path = require('path');
const {browser, checker, launch, serve, finish} = require('./harness.cjs');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

// `ncurve gen --list`: each curve ("  NAME  doc" at the line's start) with its "--NAME VALUE" defaults
function genList() {
  const text = execFileSync(ncurve, ['gen', '--list'], {encoding: 'utf8'});
  const curves = [];
  for (const line of text.split('\n')) {
    let m = /^ {2}(\S+) +\S/.exec(line);
    if (m && m[1] !== 'expr') { curves.push({name: m[1], params: {}}); continue; }
    m = /^ {2} +--(\S+) (\S+) {2}\(/.exec(line);
    if (m && curves.length && m[1] !== 'from') curves[curves.length - 1].params[m[1]] = Number(m[2]);
  }
  return curves;
}

(async () => {
  const listed = genList();
  const {server, port} = await serve(ncurve, [path.join(src, 'examples/spiral.nc')]);
  const {context, close} = await launch(driver, chromium, {width: 1400, height: 860});
  await finish({check, counts, out}, async () => {
    const page = await context.newPage();
    page.setDefaultTimeout(60000);
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    page.on('console', (m) => { if (m.type() === 'error' && !/status of 400/.test(m.text())) errors.push(m.text()); });
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => window.ncurveWorkbench && window.ncurveWorkbench.runs >= 1);
    const runs = () => page.evaluate(() => ncurveWorkbench.runs);
    const ran = (n) => page.waitForFunction((k) => ncurveWorkbench.runs > k && ncurveWorkbench.settled(), n);
    const text = (id) => page.evaluate((i) => document.getElementById(i).textContent, id);
    await page.click('button[data-tab="gen"]');

    // the list: gen --list's curves in its order, then the expression
    const options = await page.evaluate(() => [...document.getElementById('gen-curve').options].map((o) => o.value));
    check(listed.length >= 5 && options.join() === [...listed.map((c) => c.name), 'expr'].join(),
          `the curves of gen --list (${listed.map((c) => c.name).join(' ')}) and expr: ${options.join(' ')}`);
    for (const c of listed) {
      await page.selectOption('#gen-curve', c.name);
      const got = await page.evaluate(() => Object.fromEntries([...document.querySelectorAll('#gen-fields input')].map((i) => [i.dataset.param, Number(i.value)])));
      const same = Object.keys(got).join() === Object.keys(c.params).join() &&
        Object.keys(got).every((k) => Math.abs(got[k] - c.params[k]) <= 1e-9 * Math.max(1, Math.abs(c.params[k])));
      check(same, `${c.name}: its defaults filled in (${JSON.stringify(got)}; gen --list ${JSON.stringify(c.params)})`);
    }
    check(await page.isHidden('#gen-expr'), 'the expression fields hidden for a listed curve');

    // an expression: a circle of radius 10 about the origin, t in degrees
    const tol = 0.01;
    await page.selectOption('#gen-curve', 'expr');
    check(await page.isVisible('#gen-expr') && (await page.$$('#gen-fields input')).length === 0 && await page.inputValue('#gen-params') === '',
          'expr: its fields shown, no parameters');
    await page.fill('#gen-x', '10*COS[t]');
    await page.fill('#gen-y', '10*SIN[t]');
    await page.fill('#gen-from', '0');
    await page.fill('#gen-to', '360');
    await page.fill('#gen-tol', String(tol));
    await page.selectOption('#gen-form', 'expanded');
    let n = await runs();
    await page.click('#gen');
    await ran(n);
    check(await text('gen-error') === '', `no error (${await text('gen-error')})`);
    const circle = await page.evaluate(() => {
      const B = ncurveWorkbench.plot.moves, r = [], turn = [];
      for (let j = 0; j < B.count; j++) {
        if (B.kind[j] === 0) continue;  // rapids: to the start above the part
        const s = [0, 1, 2].map((k) => B.start[3 * j + k]), e = [0, 1, 2].map((k) => B.end[3 * j + k]);
        r.push(Math.hypot(e[0], e[1]), Math.hypot((s[0] + e[0]) / 2, (s[1] + e[1]) / 2));
        if (B.kind[j] === 1 && s[2] === e[2]) {
          let d = Math.atan2(e[1], e[0]) - Math.atan2(s[1], s[0]);
          if (d < -Math.PI) d += 2 * Math.PI;
          turn.push(d);
        }
      }
      return {ok: ncurveWorkbench.summary.ok, text: ncurveWorkbench.editor.text, r, moves: turn.length,
              turn: turn.reduce((a, b) => a + b, 0) * 180 / Math.PI};
    });
    const far = Math.max(...circle.r.map((r) => Math.abs(r - 10)));
    check(circle.ok && /EXPR/.test(circle.text) && circle.moves > 20, `expr generated into the editor and ran (${circle.moves} lines on the circle)`);
    check(far <= tol, `every move at feed (ends and middles) within 10 ± ${tol} of the origin (at most ${far.toFixed(5)} off)`);
    check(Math.abs(circle.turn - 360) < 1e-6, `the lines go once around (${circle.turn.toFixed(6)} degrees)`);
    await page.screenshot({path: path.join(out, 'workbench-gen-expr.png')});

    // a bad expression: the server's error beside the button
    await page.fill('#gen-x', '10*COZ[t]');
    await page.click('#gen');
    await page.waitForFunction(() => document.getElementById('gen-error').textContent !== '');
    const bad = await text('gen-error');
    check(/^400: /.test(bad) && bad.includes('COZ'), `a bad expression's error shown: ${bad}`);
    await page.fill('#gen-x', '10*COS[t]');

    // gen's forms; each generated program runs in the page as gen measured it (a cycle with the
    // parameter gen says to set), and is the current program, named so in the menu and diagnostics
    const forms = await page.evaluate(() => [...document.getElementById('gen-form').options].map((o) => o.value));
    check(forms.join() === 'expanded,arcs,macro,adaptive-macro,cycle', `the forms of gen --form: ${forms.join(' ')}`);
    // each named as gen --help names it, what it makes after it
    const named = await page.evaluate(() => [...document.getElementById('gen-form').options].map((o) => o.text));
    check(named.every((t, i) => t === forms[i] || t.startsWith(forms[i] + ' (')), `the forms named as the CLI's: ${named.join(' | ')}`);
    await page.selectOption('#gen-curve', 'ellipse');
    await page.fill('#gen-tol', '0.005');
    for (const form of ['macro', 'adaptive-macro', 'cycle']) {
      await page.selectOption('#gen-form', form);
      n = await runs();
      await page.click('#gen');
      await ran(n);
      const g = await page.evaluate(() => ({ok: ncurveWorkbench.summary.ok, err: document.getElementById('gen-error').textContent,
        out: document.getElementById('gen-out').textContent, colour: ncurveWorkbench.colour,
        file: document.getElementById('file').selectedOptions[0].text}));
      check(g.ok && g.err === '' && g.colour.mode === 'deviation' && g.colour.coloured > 20 && g.colour.most <= 0.005 + 1e-9 &&
            (form !== 'cycle' || /No\.6051 = 103/.test(g.out)) && g.file === 'generated.nc (generated)',
            `form ${form}: generated, ran (${g.ok}), ${g.colour.coloured} moves by deviation, max ${g.colour.most}; menu "${g.file}"`);
    }
    // an error typed into the generated program: its diagnostic names generated.nc
    n = await runs();
    await page.evaluate(() => {
      const t = ncurveWorkbench.editor.input;
      t.focus();
      t.setSelectionRange(t.value.indexOf('M30'), t.value.indexOf('M30'));
    });
    await page.keyboard.type('#1=[1+\n');
    await ran(n);
    const d = await page.evaluate(() => ({diags: ncurveWorkbench.diagnostics.map((x) => x.file),
      where: [...document.querySelectorAll('#diags .where')].map((e) => e.textContent)}));
    check(d.diags.length > 0 && d.diags.every((f) => f === 'generated.nc') && d.where.every((w) => w.startsWith('generated.nc:')),
          `the generated program's diagnostics name it (${d.where.join(' ')})`);
    // a lathe curve on the mill: gen's warning, in its words, beside the button
    await page.selectOption('#gen-curve', 'hyperbola');
    await page.selectOption('#gen-form', 'expanded');
    n = await runs();
    await page.click('#gen');
    await ran(n);
    const warned = await text('gen-warnings');
    check(/^warning: hyperbola is a lathe curve; without a lathe profile this is a mill program/.test(warned),
          `gen's warning shown: ${warned.slice(0, 80)}…`);
    await page.screenshot({path: path.join(out, 'workbench-gen-warning.png')});
    // another program opened: the generated one's messages go
    n = await runs();
    await page.selectOption('#file', 'spiral.nc');
    await ran(n);
    const left = await page.evaluate(() => ['gen-error', 'gen-warnings', 'gen-out'].map((id) => document.getElementById(id).textContent).join(''));
    check(left === '', `spiral.nc opened: Generate's messages cleared ("${left.slice(0, 60)}")`);
    await page.selectOption('#gen-curve', 'expr');

    // a profile from a file: the lathe's TOML, chosen through the selector's file entry
    const lathe = path.join(src, 'profiles/fanuc-lathe.toml');
    n = await runs();
    try {
      const [chooser] = await Promise.all([page.waitForEvent('filechooser', {timeout: 5000}),
        page.selectOption('#machine', '\u0000file')]);
      await chooser.setFiles(lathe);
    } catch (e) {  // no picker opened from a script's change: the input directly
      console.log(`(the file picker did not open: ${e.message.split("\n")[0]}; the input set directly)`);
      await page.setInputFiles('#machine-file', lathe);
    }
    await ran(n);
    const w = await page.evaluate(() => {
      const s = document.getElementById('machine');
      return {shown: s.options[s.selectedIndex].text, machine: ncurveWorkbench.summary.machine,
              lathe: ncurveWorkbench.plot.moves.lathe, view: ncurveWorkbench.plot.state().view,
              views: ncurveWorkbench.plot.views, status: document.getElementById('status').className};
    });
    check(w.shown.includes('fanuc-lathe.toml'), `the file's name in the selector (${w.shown})`);
    check(w.machine === 'FANUC 0i-TF 2-axis lathe' && w.lathe && /ok|alarm/.test(w.status),
          `the page runs on the file's lathe (${w.machine})`);
    check(w.view === 'zx' && w.views.includes('zx'), `the lathe's ZX view (${w.view}; views ${w.views.join(' ')})`);
    // a lathe curve generated on it
    await page.selectOption('#gen-curve', 'hyperbola');
    n = await runs();
    await page.click('#gen');
    await ran(n);
    const h = await page.evaluate(() => ({ok: ncurveWorkbench.summary.ok, machine: ncurveWorkbench.summary.machine,
      err: document.getElementById('gen-error').textContent, view: ncurveWorkbench.plot.state().view}));
    check(h.ok && h.err === '' && h.machine === 'FANUC 0i-TF 2-axis lathe' && h.view === 'zx',
          `the hyperbola generated on the file's lathe (${JSON.stringify(h)})`);
    check(await text('gen-warnings') === '', 'on a lathe, no warning');
    await page.screenshot({path: path.join(out, 'workbench-machine-file.png')});

    // a broken profile: the server's 400 in the status line
    await page.setInputFiles('#machine-file', {name: 'broken.toml', mimeType: 'text/plain',
      buffer: Buffer.from('name = "broken"\nkind = "drill"\n')});
    await page.waitForFunction(() => /^400: /.test(document.getElementById('status').textContent));
    const st = await page.evaluate(() => {
      const s = document.getElementById('machine');
      return {text: document.getElementById('status').textContent, cls: document.getElementById('status').className,
              shown: s.options[s.selectedIndex].text};
    });
    check(st.cls.includes('alarm') && st.text.length > 6 && st.shown.includes('broken.toml'),
          `a broken profile: ${st.text} (selector: ${st.shown})`);
    await page.screenshot({path: path.join(out, 'workbench-machine-broken.png')});
    check(errors.length === 0, `no script errors (${errors.join('; ')})`);
  }, async () => {
    await close();
    server.kill();
  });
})();
