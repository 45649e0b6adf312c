// `ncurve run --html` in a real browser: headless Chromium (Debian's), driven by playwright-core.
//   node backplot.test.cjs NCURVE SOURCE_DIR OUT_DIR NODE_MODULES
// Opens the pages of shipped examples and checks what is drawn: the number of moves against the
// run's, a WebGL canvas that is not blank (pixels of a screenshot), the block shown when hovering
// a move, the view buttons, the alarm, a rotary axis's range and ends, a lathe's axes and centre hole, a hostile
// comment kept as text, the programmed contour beside a compensated path, the header's facts each
// on one row from 1024 to 1920 px. Screenshots go to OUT_DIR for a person to look at. Exit 77 (skipped) where no Chromium is installed.
'use strict';
const {execFileSync} = require('child_process');
const fs = require('fs');
const path = require('path');
const {browser, checker, launch} = require('./harness.cjs');
const zlib = require('zlib');

const [ncurve, src, out, modules] = process.argv.slice(2);
const {chromium, driver} = browser(modules, out);
const {check, counts} = checker();

// runs ncurve; its standard output, whatever the exit status
function run(args) {
  try {
    return execFileSync(ncurve, args, {encoding: 'utf8', maxBuffer: 1 << 28, stdio: ['ignore', 'pipe', 'pipe']});
  } catch (e) {
    if (e.status === 1) return e.stdout;  // an alarm
    throw e;
  }
}
// the summary (JSON) and the motions (JSON Lines) of a run, and its page
function page_of(name, program, extra) {
  const html = path.join(out, `${name}.html`);
  const summary = JSON.parse(run(['run', program, ...extra, '--json', '--html', html]));
  const jsonl = run(['run', program, ...extra, '--format', 'jsonl']);
  const motions = jsonl.split('\n').filter((l) => l.trim()).map((l) => JSON.parse(l))
    .filter((m) => m.kind === 'rapid' || m.kind === 'line' || m.kind === 'arc');
  return {html, summary, motions};
}

// RGB pixels of a PNG screenshot (8-bit, not interlaced: what Chromium writes)
function decodePng(buf) {
  let at = 8, width = 0, height = 0, channels = 0;
  const idat = [];
  while (at < buf.length) {
    const len = buf.readUInt32BE(at), type = buf.toString('ascii', at + 4, at + 8);
    const body = buf.subarray(at + 8, at + 8 + len);
    if (type === 'IHDR') {
      width = body.readUInt32BE(0), height = body.readUInt32BE(4);
      channels = {2: 3, 6: 4}[body[9]];
      if (body[8] !== 8 || !channels || body[12]) throw new Error('unexpected PNG format');
    } else if (type === 'IDAT') idat.push(body);
    at += 12 + len;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = width * channels, px = Buffer.alloc(height * stride);
  for (let y = 0; y < height; y++) {
    const f = raw[y * (stride + 1)], line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    for (let x = 0; x < stride; x++) {
      const a = x >= channels ? px[y * stride + x - channels] : 0, b = y ? px[(y - 1) * stride + x] : 0;
      const c = x >= channels && y ? px[(y - 1) * stride + x - channels] : 0;
      let v = line[x];
      if (f === 1) v += a;
      else if (f === 2) v += b;
      else if (f === 3) v += (a + b) >> 1;
      else if (f === 4) {
        const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
        v += pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      }
      px[y * stride + x] = v & 255;
    }
  }
  return {width, height, channels, px};
}
// how many pixels are near each colour
function countColours(png, colours) {
  const n = colours.map(() => 0);
  let other = 0;
  for (let i = 0; i < png.width * png.height; i++) {
    const o = i * png.channels, r = png.px[o], g = png.px[o + 1], b = png.px[o + 2];
    let hit = false;
    colours.forEach((c, k) => {
      if (Math.abs(r - c[0]) + Math.abs(g - c[1]) + Math.abs(b - c[2]) < 90) n[k]++, hit = true;
    });
    if (!hit && r + g + b < 600) other++;
  }
  return {n, other};
}

async function open(context, file) {
  const page = await context.newPage();
  page.setDefaultTimeout(60000);
  const dialogs = [], errors = [];
  page.on('dialog', (d) => { dialogs.push(d.message()); d.dismiss().catch(() => {}); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.goto('file://' + file);
  await page.waitForFunction(() => window.ncurveBackplot && 'ready' in window.ncurveBackplot);
  await page.waitForTimeout(300);
  return {page, dialogs, errors};
}

// the index of a motion whose middle lies on its own (no other motion's within 6 px) and inside the view
async function lonelyMove(page, motions, kind) {
  return page.evaluate(([count, kind]) => {
    const B = window.ncurveBackplot, pts = [];
    for (let i = 0; i < count; i++) pts.push(B.screenOf(i));
    const W = innerWidth, H = innerHeight;
    for (let k = 0; k < count; k++) {
      const i = (Math.floor(count / 2) + k) % count;
      if (kind !== undefined && B.plot.moves.kind[i] !== kind) continue;
      const p = pts[i];
      if (p.x < 60 || p.y < 150 || p.x > W - 60 || p.y > H - 80) continue;
      if (pts.every((q, j) => j === i || Math.hypot(q.x - p.x, q.y - p.y) > 6)) return i;
    }
    return -1;
  }, [motions.length, kind]);
}

(async () => {
  const {context, close} = await launch(driver, chromium, {width: 1280, height: 800});
  try {
    // a mill program: the spiral
    {
      const {html, summary, motions} = page_of('browser_spiral', path.join(src, 'examples/spiral.nc'), []);
      const {page, dialogs, errors} = await open(context, html);
      const B = await page.evaluate(() => ({ready: window.ncurveBackplot.ready, error: window.ncurveBackplot.error,
        moveCount: window.ncurveBackplot.moveCount, kinds: window.ncurveBackplot.kinds, view: window.ncurveBackplot.view}));
      check(B.ready, `spiral: the page drew (${B.error || 'WebGL'})`);
      check(B.moveCount === summary.motions && B.moveCount === motions.length,
            `spiral: ${B.moveCount} moves drawn, the run made ${summary.motions}`);
      check(B.kinds.rapid === summary.moves.rapid && B.kinds.feed === summary.moves.line && B.kinds.arc === summary.moves.arc,
            `spiral: moves by kind ${JSON.stringify(B.kinds)}`);
      check(B.view === 'iso', `spiral: a mill opens in the iso view (${B.view})`);
      const shot = await page.screenshot({path: path.join(out, 'browser_spiral_iso.png')});
      const {n, other} = countColours(decodePng(shot), [[0x15, 0x65, 0xc0], [0xef, 0x6c, 0x00]]);
      check(n[0] > 300 && n[1] > 20, `spiral: the canvas shows feed (${n[0]} px) and rapid (${n[1]} px) lines`);
      check(other > 200, `spiral: axes and labels drawn (${other} dark px)`);
      const header = await page.textContent('#summary');
      check(header.includes('spiral.nc') && header.includes('completed') && header.includes(`${summary.motions}`),
            'spiral: the header names the program, the result and the moves');

      // hover a known move: its file:line and block text from the run's own JSON Lines
      const i = await lonelyMove(page, motions, 1);
      check(i >= 0, `spiral: a move to hover (${i})`);
      const p = await page.evaluate((i) => window.ncurveBackplot.screenOf(i), i);
      await page.mouse.move(p.x - 30, p.y - 30);
      await page.mouse.move(p.x, p.y, {steps: 3});
      await page.waitForSelector('#tip:not([hidden])', {timeout: 10000}).catch(() => {});
      const tip = await page.textContent('#tip');
      const hovered = await page.evaluate(() => window.ncurveBackplot.hovered);
      check(hovered === i, `spiral: the move under the pointer is the one aimed at (${hovered}, ${i})`);
      check(tip.includes(`spiral.nc:${motions[i].line}`), `spiral: hovering shows its line ${motions[i].line}: "${tip}"`);
      await page.screenshot({path: path.join(out, 'browser_spiral_hover.png')});
      // a click selects the block's moves
      await page.mouse.click(p.x, p.y);
      const sel = await page.textContent('#selection');
      check(/selected: \d+ moves? of this block/.test(sel) && sel.includes(`:${motions[i].line}`), `spiral: click selects the block: "${sel}"`);

      // the view buttons move the camera
      const cams = {};
      for (const v of ['top', 'front', 'side', 'iso']) {
        await page.click(`#views button[data-view="${v}"]`);
        await page.waitForTimeout(150);
        cams[v] = await page.evaluate(() => ({view: window.ncurveBackplot.view, camera: window.ncurveBackplot.camera}));
        await page.screenshot({path: path.join(out, `browser_spiral_${v}.png`)});
      }
      const dir = (c) => { const [x, y, z] = c.camera.position, t = c.camera.target, d = Math.hypot(x - t[0], y - t[1], z - t[2]); return [(x - t[0]) / d, (y - t[1]) / d, (z - t[2]) / d]; };
      const near = (a, b) => a.every((v, k) => Math.abs(v - b[k]) < 1e-3);
      check(near(dir(cams.top), [0, 0, 1]) && cams.top.view === 'top', `spiral: Top looks down Z (${dir(cams.top).map((v) => v.toFixed(3))})`);
      check(near(dir(cams.front), [0, -1, 0]), `spiral: Front looks along +Y (${dir(cams.front).map((v) => v.toFixed(3))})`);
      check(near(dir(cams.side), [1, 0, 0]), `spiral: Side looks along -X (${dir(cams.side).map((v) => v.toFixed(3))})`);
      check(near(dir(cams.iso), [1 / Math.sqrt(3), -1 / Math.sqrt(3), 1 / Math.sqrt(3)]), 'spiral: Iso from X+, Y-, Z+');
      // dragging orbits: the camera moves, the named view is left
      const box = await page.locator('canvas').boundingBox();
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      await page.mouse.down();
      await page.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2 + 40, {steps: 5});
      await page.mouse.up();
      const orbit = await page.evaluate(() => ({view: window.ncurveBackplot.view, camera: window.ncurveBackplot.camera}));
      check(!near(dir(orbit), dir(cams.iso)) && orbit.view === '', 'spiral: dragging rotates the view');
      check(dialogs.length === 0 && errors.length === 0, `spiral: no script errors (${errors.join('; ')})`);
      await page.close();
    }

    // an alarm: the alarm block marked
    {
      const {html, summary} = page_of('browser_alarm', path.join(src, 'examples/alarm.nc'), []);
      const {page, errors} = await open(context, html);
      const header = await page.textContent('#summary');
      check(header.includes('ALARM MC3001') && header.includes('line 9') && header.includes('DEPTH #100 NOT SET'),
            `alarm: the header says the alarm: "${header.slice(0, 200)}"`);
      const marker = await page.$('.ncurve-label.marker.alarm');
      check(marker && (await marker.isVisible()) && (await marker.textContent()) === 'MC3001 line 9', 'alarm: marked in the view');
      check((await page.evaluate(() => window.ncurveBackplot.moveCount)) === summary.motions, 'alarm: the moves before it drawn');
      // the ✕ (the marker's first 12 px) on the alarm point X0 Y0 Z5, in every view
      for (const v of ['top', 'front', 'iso']) {
        await page.click(`#views button[data-view="${v}"]`);
        await page.waitForTimeout(100);
        const at = await page.evaluate(() => window.ncurveBackplot.screenOfPoint([0, 0, 5]));
        const box = await marker.boundingBox();
        const cx = box.x + 6, cy = box.y + box.height / 2;
        check(Math.abs(cx - at.x) < 4 && Math.abs(cy - at.y) < 4,
              `alarm: ${v}: the cross at (${cx.toFixed(0)}, ${cy.toFixed(0)}) on the alarm point (${at.x.toFixed(0)}, ${at.y.toFixed(0)})`);
      }
      await page.screenshot({path: path.join(out, 'browser_alarm.png')});
      check(errors.length === 0, `alarm: no script errors (${errors.join('; ')})`);
      await page.close();
    }

    // under G41 D1 of radius 5 (a profile setting offset 1), a 40 x 30 contour clockwise whose top is
    // a half circle G02 about (20, 30): the programmed contour drawn dashed through the program's
    // corners, its arc on the circle of radius 20 about (20, 30), beside the tool centre's path
    {
      const program = path.join(out, 'browser_programmed.nc'), profile = path.join(out, 'browser_programmed.toml');
      fs.writeFileSync(program, 'G90 G17 G21 G54 G00 X-20. Y-20. Z5.\nG01 Z-1. F200.\nG41 D1 G01 X0 Y0 F500.\nY30.\n' +
                       'G02 X40. Y30. I20. J0\nG01 Y0\nX0\nG40 G01 X-20. Y-20.\nG00 Z5.\nM30\n');
      fs.writeFileSync(profile, '[machine]\noffset_memory = "A"\n[tool_offsets]\n"1" = 5\n');
      const {page, errors} = await open(context, page_of('browser_programmed', program, ['--machine', profile]).html);
      const drawn = await page.evaluate(() => ({state: ncurveBackplot.plot.state().programmed, points: ncurveBackplot.plot.programmedPoints(),
        legend: document.getElementById('legend').textContent}));
      const pts = [];
      for (let v = 0; v < drawn.points.length; v += 3) pts.push(drawn.points.slice(v, v + 3));
      const near = (p, x, y) => Math.abs(p[0] - x) < 1e-4 && Math.abs(p[1] - y) < 1e-4;
      const arc = pts.filter((p) => p[1] > 30 + 1e-3);
      check(drawn.state && drawn.state.moves === 6 && [[0, 0], [0, 30], [40, 30], [40, 0], [-20, -20]].every(([x, y]) => pts.some((p) => near(p, x, y))) &&
            arc.length >= 8 && arc.every((p) => Math.abs(Math.hypot(p[0] - 20, p[1] - 30) - 20) < 1e-3) && /programmed 6/.test(drawn.legend),
            `programmed: ${drawn.state && drawn.state.moves} moves dashed through the corners, ${arc.length} points of the arc 20 from (20, 30)`);
      await page.click('#legend input[type=checkbox]');
      check((await page.evaluate(() => ncurveBackplot.plot.state().programmed.visible)) === false, 'programmed: the legend\'s box hides it');
      await page.click('#legend input[type=checkbox]');
      await page.evaluate(() => ncurveBackplot.plot.setView('top'));
      await page.screenshot({path: path.join(out, 'browser_programmed.png')});
      // from 1024 px up the header's rows wrap between its facts, each name on the row of its value
      const apart = [];
      for (let width = 1024; width <= 1920; width += 8) {
        await page.setViewportSize({width, height: 768});
        const names = await page.evaluate(() => [...document.querySelectorAll('#summary dt')].filter((dt) => {
          const dd = dt.nextElementSibling;
          return !dd || Math.abs(dt.getClientRects()[0].top - dd.getClientRects()[0].top) > 2;
        }).map((dt) => dt.textContent));
        if (names.length) apart.push(`${width} px: ${names.join(', ')}`);
      }
      check(apart.length === 0, `1024 to 1920 px: each fact's name on the row of its value (apart: ${apart.slice(0, 3).join('; ') || 'none'})`);
      await page.setViewportSize({width: 1024, height: 768});
      await page.screenshot({path: path.join(out, 'browser_programmed-1024.png')});
      await page.setViewportSize({width: 1280, height: 800});
      check(errors.length === 0, `programmed: no script errors (${errors.join('; ')})`);
      await page.close();
    }

    // run --setup --html: the cut part shaded under the path, the groove darker than the top
    {
      const {html, summary} = page_of('browser_part', path.join(src, 'examples/spiral.nc'),
                                      ['--setup', path.join(src, 'examples/spiral.setup.toml'), '--resolution', '0.1']);
      const {page, errors} = await open(context, html);
      const part = await page.evaluate(() => window.ncurveBackplot.plot.state().part);
      // 400 x 400 points: 2 * 399^2 triangles on top and 2 a boundary edge on the walls
      check(part === 2 * 399 * 399 + 2 * 4 * 399, `part: the mesh of the 400 x 400 cells drawn (${part} triangles)`);
      const header = await page.textContent('#summary');
      check(header.includes('mm³ removed') && header.includes('0 findings'), `part: the header says what was removed: "${header.slice(0, 400)}"`);
      await page.evaluate(() => window.ncurveBackplot.plot.setView('top'));
      await page.evaluate(() => window.ncurveBackplot.plot.render());
      // the groove's floor (0.5 deep, the deepest) is darker than the untouched top beside it
      const shade = async (p) => {
        const at = await page.evaluate((p) => window.ncurveBackplot.screenOfPoint(p), p);
        const png = decodePng(await page.screenshot({clip: {x: at.x - 1, y: at.y - 1, width: 3, height: 3}}));
        return png.px[4 * png.channels] + png.px[4 * png.channels + 1] + png.px[4 * png.channels + 2];
      };
      const floor = await shade([-7.3, -3.0, -0.5]), top = await shade([-3.0, -6.0, 0]);
      check(floor + 60 < top, `part: the groove (${floor}) drawn darker than the top (${top})`);
      await page.screenshot({path: path.join(out, 'browser_part.png')});
      check(errors.length === 0 && summary.verify.verified, `part: no script errors (${errors.join('; ')})`);
      await page.close();
      const plain = await open(context, page_of('browser_no_part', path.join(src, 'examples/spiral.nc'), []).html);
      check((await plain.page.evaluate(() => window.ncurveBackplot.plot.state().part)) === 0, 'part: none without --verify');
      await plain.page.close();
    }

    // a lathe's part: the bar's half-section revolved about Z, drawn at its radius on both sides of
    // the axis (D50 beyond the chuck jaw, where the program does not cut), nothing beyond it
    {
      const {html, summary, motions} = page_of('browser_lathe_part', path.join(src, 'examples/lathe-mrc.nc'),
                                      ['--machine', 'fanuc-lathe', '--setup', path.join(src, 'examples/lathe-mrc.setup.toml')]);
      const {page, errors} = await open(context, html);
      const part = await page.evaluate(() => window.ncurveBackplot.plot.state().part);
      check(part > 0 && part % 192 === 0, `lathe part: its contours revolved in 96 steps (${part} triangles)`);
      // the ZX view fits the cuts, not the rapids from and to home (X300 Z250): the cuts' Z range
      // (from the run's lines and arcs) fills at least half the view's width
      const cutZ = motions.filter((m) => m.kind !== 'rapid').flatMap((m) => [m.start[2], m.end[2]]);
      const z0 = Math.min(...cutZ), z1 = Math.max(...cutZ);
      const [sz0, sz1, width] = await page.evaluate(([a, b]) => [window.ncurveBackplot.screenOfPoint([0, 0, a]).x,
        window.ncurveBackplot.screenOfPoint([0, 0, b]).x, document.querySelector('canvas').clientWidth], [z0, z1]);
      check(sz1 - sz0 >= width / 2, `lathe fit: the cuts' Z ${z0} … ${z1} take ${(sz1 - sz0).toFixed(0)} of ${width} px`);
      await page.screenshot({path: path.join(out, 'browser_lathe_fit.png')});
      // a wheel notch over a point zooms about it: the point stays under the pointer, a fifth larger
      const pointAt = () => page.evaluate(() => [window.ncurveBackplot.screenOfPoint([30, 0, -40]),
        window.ncurveBackplot.plot.state().camera.zoom]);
      const [before, zoom0] = await pointAt();
      await page.mouse.move(before.x, before.y);
      await page.mouse.wheel(0, -100);
      await page.waitForTimeout(100);
      const [after, zoom1] = await pointAt();
      check(Math.hypot(after.x - before.x, after.y - before.y) < 1 && Math.abs(zoom1 / zoom0 - 1.2) < 1e-6,
            `wheel: X30 Z-40 stays under the pointer (${before.x.toFixed(1)}, ${before.y.toFixed(1)} -> ` +
            `${after.x.toFixed(1)}, ${after.y.toFixed(1)}), zoom x${(zoom1 / zoom0).toFixed(3)}`);
      await page.evaluate(() => window.ncurveBackplot.plot.fit());
      // Fit all: the home rapids too (the uncut bar by the chuck in view for the checks below)
      await page.evaluate(() => window.ncurveBackplot.plot.fitAll());
      const [az0, az1] = await page.evaluate(([a, b]) => [window.ncurveBackplot.screenOfPoint([0, 0, a]).x,
        window.ncurveBackplot.screenOfPoint([0, 0, b]).x], [z0, z1]);
      check(az1 - az0 < 0.9 * (sz1 - sz0), `lathe fit all: the cuts drawn smaller (${(az1 - az0).toFixed(0)} px)`);
      await page.evaluate(() => window.ncurveBackplot.plot.render());
      const colour = async (p) => {
        const at = await page.evaluate((p) => window.ncurveBackplot.screenOfPoint(p), p);
        const png = decodePng(await page.screenshot({clip: {x: at.x - 1, y: at.y - 1, width: 3, height: 3}}));
        return [0, 1, 2].map((k) => png.px[4 * png.channels + k]);
      };
      const apart = (a, b) => Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]);
      // (the ZX view fits the path: the chuck's end of the bar, Z-70, is at the page's left, the axis
      // low on it, so below the axis only a little of the part is in view, above the legend: two lines
      // with the programmed contour's entry, G70 running under G42)
      const background = await colour([40, 0, -70]);
      const inside = [await colour([24, 0, -70]), await colour([0, 0, -70]), await colour([-5, 0, -70])];
      const outside = [await colour([26.5, 0, -70]), await colour([5, 0, 15])];
      check(inside.every((c) => apart(c, background) > 60),
            `lathe part: drawn within radius 25 on both sides of the axis (${JSON.stringify(inside)} against ${background})`);
      check(outside.every((c) => apart(c, background) < 20),
            `lathe part: nothing beyond radius 25 or before the face (${JSON.stringify(outside)})`);
      await page.screenshot({path: path.join(out, 'browser_lathe_part.png')});
      await page.evaluate(() => window.ncurveBackplot.plot.setView('iso'));
      await page.evaluate(() => window.ncurveBackplot.plot.render());
      await page.screenshot({path: path.join(out, 'browser_lathe_part_iso.png')});
      check(errors.length === 0 && summary.verify.verified, `lathe part: no script errors (${errors.join('; ')})`);
      await page.close();
    }

    // a rapid as the machine moves it (non-linear positioning, the shipped mill: X and Y at 24 m/min, Z
    // at 15): G00 from X0 Z20 to X60 Z2 reaches Z2 after 18 / 15000 min, at X28.8, then runs along Z2;
    // the first rapid, from the power-on position X250 Y200 Z400, has a corner as each of two axes
    // arrives. With linear positioning (No.1401#1 = 1) each is one straight segment.
    {
      const prog = path.join(out, 'browser_dogleg.nc');
      fs.writeFileSync(prog, 'G90 G00 X0 Y0 Z20.\nG00 X60. Z2.\nM30\n');
      for (const [linear, segs] of [[false, 3 + 2], [true, 1 + 1]]) {
        const {html} = page_of(`browser_dogleg${linear ? '_linear' : ''}`, prog, linear ? ['--param', '1401#1=1'] : []);
        const {page, errors} = await open(context, html);
        const seg = await page.evaluate(() => window.ncurveBackplot.segments);
        check(seg.rapid === segs, `dog-leg: the rapids drawn in ${seg.rapid} segments, ${segs} expected (linear ${linear})`);
        await page.evaluate(() => window.ncurveBackplot.plot.setView('front'));
        await page.evaluate(() => window.ncurveBackplot.plot.render());
        // the strip along Z2 from X35 to X55 (dashed: some of it)
        const a = await page.evaluate(() => window.ncurveBackplot.screenOfPoint([35, 0, 2]));
        const b = await page.evaluate(() => window.ncurveBackplot.screenOfPoint([55, 0, 2]));
        const png = decodePng(await page.screenshot({clip: {x: Math.min(a.x, b.x), y: a.y - 3, width: Math.abs(b.x - a.x), height: 7}}));
        let orange = 0;  // the thin dashes blend with the white: reddish pixels
        for (let i = 0; i < png.width * png.height; i++) {
          const o = i * png.channels;
          if (png.px[o] - png.px[o + 2] > 60) orange++;
        }
        check(linear ? orange === 0 : orange > 20, `dog-leg: the leg along Z2 drawn (${orange} orange px; linear ${linear})`);
        if (!linear) await page.screenshot({path: path.join(out, 'browser_dogleg.png')});
        check(errors.length === 0, `dog-leg: no script errors (${errors.join('; ')})`);
        await page.close();
      }
    }

    // a lathe with a C axis: the header gives the extents in axis order (X, Z, C), not sorted
    {
      const prog = path.join(src, 'tests/programs/lathe/lt_drill_c_axis');
      const {html} = page_of('browser_lathe_c', prog + '.nc', ['--machine', prog + '.toml']);
      const {page} = await open(context, html);
      const header = await page.textContent('#summary');
      check(/X⌀.*Z.*C/.test(header), `lathe with C: extents in axis order: "${header.slice(0, 300)}"`);
      await page.close();
    }

    // a rotary A axis, not drawn: the header says so with its range, a move's hover text gives its A end
    {
      const {html, motions} = page_of('browser_4axis', path.join(src, 'examples/4-axis.nc'),
                                      ['--machine', path.join(src, 'profiles/fanuc-4axis-helicoid.toml')]);
      const {page, errors} = await open(context, html);
      const header = await page.textContent('#summary');
      check(header.includes('axes not drawn') && header.includes('A 0 … 360°'), `4-axis: the header names A's range: "${header.slice(0, 400)}"`);
      const i = motions.findIndex((m) => m.end_abc && m.end_abc[0] === 90);
      check(i >= 0, '4-axis: a move to A90 in the run');
      await page.evaluate((i) => window.ncurveBackplot.plot.hover(i), i);
      const tip = await page.textContent('#tip');
      check(tip.includes(`4-axis.nc:${motions[i].line}`) && / A90( |$)/.test(tip), `4-axis: the hover text gives the move's A end: "${tip}"`);
      await page.screenshot({path: path.join(out, 'browser_4axis.png')});
      check(errors.length === 0, `4-axis: no script errors (${errors.join('; ')})`);
      await page.close();
    }

    // a lathe: Z across, X up as a diameter, arcs drawn
    {
      const {html, summary} = page_of('browser_lathe', path.join(src, 'examples/lathe-mrc.nc'), ['--machine', 'fanuc-lathe']);
      const {page, errors} = await open(context, html);
      const B = await page.evaluate(() => ({n: window.ncurveBackplot.moveCount, kinds: window.ncurveBackplot.kinds,
        view: window.ncurveBackplot.view, segments: window.ncurveBackplot.segments}));
      check(B.n === summary.motions, `lathe: ${B.n} moves drawn, the run made ${summary.motions}`);
      check(B.view === 'zx', 'lathe: opens on the ZX plane');
      check(B.kinds.arc === summary.moves.arc && (B.kinds.arc === 0 || B.segments.arc > 4 * B.kinds.arc),
            `lathe: arcs drawn as arcs (${B.kinds.arc} arcs, ${B.segments.arc} segments)`);
      const names = await page.$$eval('.ncurve-label.axis-name', (l) => l.filter((e) => e.style.display !== 'none').map((e) => e.textContent));
      check(names.includes('Z, mm') && names.includes('X (diameter), mm'), `lathe: axes ${JSON.stringify(names)}`);
      // the centre hole (G00 X0 Z3., G74 Z-20.) is the one hole, marked at X0 Z3; the roughing passes
      // along Z (off the axis) are none
      const holes = await page.evaluate(() => ({list: window.ncurveBackplot.plot.state().holes,
        legend: document.getElementById('legend').textContent}));
      check(JSON.stringify(holes.list) === '[[0,0,3]]' && holes.legend.includes('holes 1'),
            `lathe: the G74 centre hole marked at X0 Z3 (${JSON.stringify(holes.list)}), counted in the legend`);
      await page.screenshot({path: path.join(out, 'browser_lathe.png')});
      check(errors.length === 0, `lathe: no script errors (${errors.join('; ')})`);
      await page.close();
    }

    // a program in inches: the axes in inches; a click on empty space clears the selection
    {
      const {html, motions} = page_of('browser_inch', path.join(src, 'examples/inch.nc'), []);
      const {page, errors} = await open(context, html);
      await page.click('#views button[data-view="top"]');
      await page.waitForTimeout(150);
      const names = await page.$$eval('.ncurve-label.axis-name', (l) => l.filter((e) => e.style.display !== 'none').map((e) => e.textContent));
      check(names.includes('X, in') && names.includes('Y, in'), `inch: axes in inches ${JSON.stringify(names)}`);
      const i = await lonelyMove(page, motions, 2);
      const p = await page.evaluate((i) => window.ncurveBackplot.screenOf(i), i);
      await page.mouse.click(p.x, p.y);
      check(!(await page.isHidden('#selection')) && (await page.textContent('#selection')).includes(`inch.nc:${motions[i].line}`),
            `inch: an arc selected by a click (line ${motions[i].line})`);
      const box = await page.locator('canvas').boundingBox();
      await page.mouse.click(box.x + 30, box.y + box.height / 2);
      check(await page.isHidden('#selection'), 'inch: a click on empty space clears the selection');
      await page.screenshot({path: path.join(out, 'browser_inch_top.png')});
      check(errors.length === 0, `inch: no script errors (${errors.join('; ')})`);
      await page.close();
    }

    // a hostile comment and a byte that is not UTF-8: text on the page, never markup or script
    {
      const prog = path.join(out, 'browser_hostile.nc');
      fs.writeFileSync(prog, Buffer.concat([Buffer.from('%\nO1234 (</script><script>alert[1]</script>)\nG90 G00 X0 Y0 Z5.\n' +
        'G01 Z-1. F100 (<img src=x onerror=alert[2]> \u2028)\nX20. (caf'), Buffer.from([0xe9]), Buffer.from(')\nY20.\nX0\nY0\nM30\n%\n')]));
      const {html, motions} = page_of('browser_hostile', prog, []);
      const {page, dialogs, errors} = await open(context, html);
      check((await page.evaluate(() => window.ncurveBackplot.moveCount)) === motions.length, 'hostile: drawn');
      const i = motions.findIndex((m) => m.line === 4);
      const p = await page.evaluate((i) => window.ncurveBackplot.screenOf(i), i);
      await page.mouse.move(p.x + 20, p.y + 20);
      await page.mouse.move(p.x, p.y, {steps: 3});
      await page.waitForTimeout(300);
      const tip = await page.textContent('#tip');
      check(tip.includes('<img src=x onerror=alert[2]>'), `hostile: the comment shown as text: "${tip}"`);
      await page.mouse.move(5, 5);
      const j = motions.findIndex((m) => m.line === 5);
      const q = await page.evaluate((i) => window.ncurveBackplot.screenOf(i), j);
      await page.mouse.move(q.x, q.y, {steps: 3});
      await page.waitForTimeout(300);
      check((await page.textContent('#tip')).includes('X20. (caf\ufffd)'), 'hostile: a byte that is not UTF-8 shown as U+FFFD');
      check(dialogs.length === 0 && (await page.$$('img')).length === 0, `hostile: no script ran (${dialogs.join(', ')})`);
      check((await page.title()).includes('browser_hostile.nc'), 'hostile: title');
      check(errors.length === 0, `hostile: no script errors (${errors.join('; ')})`);
      await page.close();
      // the comment closes at alert(1's ')': a PS0009 alarm, whose block the header shows as text
      const prog2 = path.join(out, 'browser_hostile_alarm.nc');
      fs.writeFileSync(prog2, '%\nG00 X1 Y1 (</script><script>alert(1)</script>)\nM30\n%\n');
      const second = page_of('browser_hostile_alarm', prog2, []);
      const other = await open(context, second.html);
      const header = await other.page.textContent('#summary');
      check(header.includes('ALARM PS0009') && header.includes('(</script><script>alert(1)</script>)'),
            `hostile: the alarm's block shown as text: "${header.slice(0, 300)}"`);
      check(other.dialogs.length === 0 && other.errors.length === 0, 'hostile: no script ran from the alarm block');
      await other.page.screenshot({path: path.join(out, 'browser_hostile_alarm.png')});
      await other.page.close();
    }
  } finally {
    await close();
  }
  console.log(`screenshots in ${out}`);
  console.log(`${counts.passed} passed, ${counts.failed} failed`);
  process.exit(counts.failed ? 1 : 0);
})().catch((e) => {
  console.log(`FAIL ${e.stack || e}`);
  console.log(`${counts.passed} passed, ${counts.failed + 1} failed`);
  process.exit(1);
});
