// The workbench's program editor: a plain textarea over a highlighted copy of its text (FANUC
// syntax: comments, N numbers, G/M codes, macro statements, variables), a gutter of line numbers
// (click: a breakpoint), diagnostics as wavy marks at their line and column (hover: code and
// message), and line backgrounds for the cursor's, the selected and the debugger's line.
//   const ed = NcurveEditor.create(el, {onChange(text) {}, onCursorLine(line) {}, onGutterClick(line) {}});
(function (global) {
  'use strict';
  const KEYWORDS = 'IF|WHILE|DO|END|GOTO|THEN|EQ|NE|LT|LE|GT|GE|AND|OR|XOR|MOD|SIN|COS|TAN|ASIN|ACOS|ATAN|SQRT|ABS|' +
    'BIN|BCD|ROUND|FIX|FUP|LN|EXP|POW|ADP|SETVN|POPEN|PCLOS|DPRNT|BPRNT';
  // one alternative per token class, tried left to right at each place of a line
  const TOKEN = new RegExp('(\\([^)]*\\)?)|((?<![A-Z])N\\d+)|((?<![A-Z])[GM]\\d+(?:\\.\\d+)?)|(#\\d*)|' +
    `((?<![A-Z])(?:${KEYWORDS})(?![A-Z]))|((?<![A-Z])O\\d+)|(%)`, 'gi');
  const CLASSES = ['', 'c', 'n', 'g', 'v', 'k', 'o', 'o'];
  const esc = (s) => s.replace(/[&<>]/g, (c) => (c === '&' ? '&amp;' : c === '<' ? '&lt;' : '&gt;'));

  // one line as HTML: its tokens in spans of their class
  function highlightLine(line) {
    let out = '', at = 0, m;
    TOKEN.lastIndex = 0;
    while ((m = TOKEN.exec(line))) {
      let k = 1;
      while (m[k] === undefined) k++;
      out += esc(line.slice(at, m.index)) + `<span class="${CLASSES[k]}">${esc(m[0])}</span>`;
      at = m.index + m[0].length;
    }
    return out + esc(line.slice(at));
  }

  function create(container, options) {
    options = options || {};
    const el = (tag, cls) => { const e = document.createElement(tag); e.className = cls; return e; };
    const root = el('div', 'wb-editor');
    const lines = el('div', 'wb-lines');
    const gutter = el('div', 'wb-gutter');
    const numbers = el('pre', 'wb-numbers');
    const marksG = el('div', 'wb-gutter-marks');
    gutter.append(numbers, marksG);
    const code = el('div', 'wb-code');
    const bands = el('div', 'wb-bands');  // line backgrounds, under the text
    const hl = el('pre', 'wb-hl');
    const marks = el('div', 'wb-marks');   // diagnostics' wavy lines
    const input = el('textarea', 'wb-input');
    input.spellcheck = false;
    input.wrap = 'off';
    input.setAttribute('autocapitalize', 'off');
    input.setAttribute('autocomplete', 'off');
    input.setAttribute('aria-label', 'program');
    code.append(bands, hl, marks, input);
    lines.append(gutter, code);
    const tip = el('div', 'wb-tip');
    tip.hidden = true;
    root.append(lines);
    container.append(root, tip);

    // the metrics of the monospace font
    const probe = el('span', 'wb-probe');
    probe.textContent = 'M'.repeat(100);
    hl.append(probe);
    let cw = probe.getBoundingClientRect().width / 100 || 7.8;
    probe.remove();
    const LH = 18, PAD = 6;

    let text = '', lineCount = 1, diags = [], breakpoints = new Set(), current = 0, selected = 0, cursor = 1;
    const lineStarts = () => {
      const s = [0];
      for (let i = text.indexOf('\n'); i >= 0; i = text.indexOf('\n', i + 1)) s.push(i + 1);
      return s;
    };
    let starts = [0];

    const band = (cls, line) => {
      const b = el('div', 'wb-band ' + cls);
      b.style.top = PAD + (line - 1) * LH + 'px';
      return b;
    };
    function drawBands() {
      bands.textContent = '';
      // (a line the text no longer has is not drawn)
      if (cursor <= lineCount) bands.append(band('cursor', cursor));
      for (const b of breakpoints) if (b <= lineCount) bands.append(band('break', b));
      if (selected && selected <= lineCount) bands.append(band('selected', selected));
      if (current && current <= lineCount) bands.append(band('current', current));
      marksG.textContent = '';
      for (const b of breakpoints) {
        if (b > lineCount) continue;
        const d = el('div', 'wb-bp');
        d.style.top = PAD + (b - 1) * LH + 'px';
        d.title = `breakpoint on line ${b} (click to remove)`;
        marksG.append(d);
      }
      const seen = new Set();
      for (const d of diags) {
        if (!(d.line >= 1 && d.line <= lineCount) || seen.has(d.line)) continue;
        seen.add(d.line);
        const g = el('div', 'wb-diag-g ' + d.severity);
        g.style.top = PAD + (d.line - 1) * LH + 'px';
        g.title = diags.filter((x) => x.line === d.line).map((x) => `${x.code} ${x.message}`).join('\n');
        marksG.append(g);
      }
      if (current) {
        const arrow = el('div', 'wb-arrow');
        arrow.style.top = PAD + (current - 1) * LH + 'px';
        marksG.append(arrow);
      }
    }
    function drawMarks() {
      marks.textContent = '';
      const all = text.split('\n');
      for (const d of diags) {
        if (!(d.line >= 1 && d.line <= lineCount)) continue;
        const s = all[d.line - 1] || '';
        const col = Math.max(1, Math.min(d.column || 1, s.length + 1));
        // the word at the column, or the rest of the line
        let end = col;
        while (end <= s.length && /[A-Za-z0-9#.\[\]+\-*/=]/.test(s[end - 1]) && end - col < 40) end++;
        if (end === col) end = Math.max(s.length + 1, col + 1);
        const m = el('div', 'wb-mark ' + d.severity);
        m.style.top = PAD + (d.line - 1) * LH + LH - 5 + 'px';
        m.style.left = PAD + (col - 1) * cw + 'px';
        m.style.width = Math.max(cw, (end - col) * cw) + 'px';
        m.dataset.line = d.line;
        m.dataset.column = col;
        marks.append(m);
      }
    }
    function render() {
      const all = text.split('\n');
      lineCount = all.length;
      starts = lineStarts();
      // a big text is drawn plain past its first 20,000 lines
      const big = all.length > 20000;
      hl.innerHTML = all.map((l, i) => (big && i >= 20000 ? esc(l) : highlightLine(l))).join('\n') + '\n';
      let nums = '';
      for (let i = 1; i <= lineCount; i++) nums += i + '\n';
      numbers.textContent = nums;
      let longest = 0;
      for (const l of all) if (l.length > longest) longest = l.length;
      const w = Math.ceil((longest + 4) * cw) + 2 * PAD, h = lineCount * LH + 2 * PAD;
      code.style.width = `max(100%, ${w}px)`;
      code.style.height = h + 'px';
      gutter.style.height = h + 'px';
      drawMarks();
      drawBands();
    }
    const lineAt = (pos) => {  // 1-based line of a character offset
      let lo = 0, hi = starts.length - 1;
      while (lo < hi) { const mid = (lo + hi + 1) >> 1; if (starts[mid] <= pos) lo = mid; else hi = mid - 1; }
      return lo + 1;
    };
    const noteCursor = () => {
      const l = lineAt(input.selectionStart);
      if (l === cursor) return;
      cursor = l;
      drawBands();
      if (options.onCursorLine) options.onCursorLine(l);
    };
    input.addEventListener('input', () => {
      text = input.value;
      render();
      noteCursor();
      if (options.onChange) options.onChange(text);
    });
    for (const ev of ['keyup', 'click', 'select', 'focus']) input.addEventListener(ev, noteCursor);
    document.addEventListener('selectionchange', () => { if (document.activeElement === input) noteCursor(); });
    input.addEventListener('keydown', (e) => {  // Tab types two spaces
      if (e.key !== 'Tab' || e.ctrlKey || e.altKey || e.metaKey) return;
      e.preventDefault();
      document.execCommand('insertText', false, '  ');
    });
    gutter.addEventListener('click', (e) => {
      const r = gutter.getBoundingClientRect();
      const line = Math.floor((e.clientY - r.top - PAD) / LH) + 1;
      if (line >= 1 && line <= lineCount && options.onGutterClick) options.onGutterClick(line);
    });
    // hover: the diagnostics under the pointer
    input.addEventListener('mousemove', (e) => {
      const r = code.getBoundingClientRect();
      const line = Math.floor((e.clientY - r.top - PAD) / LH) + 1;
      const here = diags.filter((d) => d.line === line);
      if (!here.length) { tip.hidden = true; return; }
      tip.textContent = '';
      for (const d of here) {
        const row = el('div', 'wb-tip-row ' + d.severity);
        const c = el('strong', '');
        c.textContent = d.code;
        row.append(c, document.createTextNode(` ${d.message}`));
        tip.append(row);
      }
      tip.hidden = false;
      const cr = container.getBoundingClientRect();
      tip.style.left = Math.min(e.clientX - cr.left + 12, cr.width - 320) + 'px';
      tip.style.top = (PAD + line * LH + r.top - cr.top + 4) + 'px';
    });
    input.addEventListener('mouseleave', () => { tip.hidden = true; });

    const reveal = (line) => {
      const top = PAD + (line - 1) * LH;
      if (top < root.scrollTop + LH || top > root.scrollTop + root.clientHeight - 2 * LH)
        root.scrollTop = Math.max(0, top - root.clientHeight / 3);
    };
    const api = {
      get text() { return text; },
      setText(t) {
        text = t;
        input.value = t;
        cursor = 1;
        render();
        root.scrollTop = 0;
      },
      setDiagnostics(list) { diags = list || []; tip.hidden = true; drawMarks(); drawBands(); },
      setBreakpoints(set) { breakpoints = set; drawBands(); },
      // the debugger's line (0: none)
      setCurrentLine(line) {
        current = line || 0;
        drawBands();
        if (current) reveal(current);
      },
      // select a line (a move clicked in the backplot): its text selected, scrolled to
      selectLine(line) {
        if (!(line >= 1 && line <= lineCount)) return;
        selected = line;
        const s = starts[line - 1], e = line < starts.length ? starts[line] - 1 : text.length;
        input.focus({preventScroll: true});
        input.setSelectionRange(s, e);
        cursor = line;
        drawBands();
        reveal(line);
      },
      cursorLine: () => cursor,
      lineCount: () => lineCount,
      lineText: (line) => text.slice(starts[line - 1], line < starts.length ? starts[line] - 1 : text.length),
      // where a line and column is on the page (tests)
      screenOf(line, column) {
        const r = code.getBoundingClientRect();
        return {x: r.left + PAD + ((column || 1) - 0.5) * cw, y: r.top + PAD + (line - 0.5) * LH};
      },
      gutterOf(line) {
        const r = gutter.getBoundingClientRect();
        return {x: r.left + r.width / 2, y: r.top + PAD + (line - 0.5) * LH};
      },
      input, root,
    };
    return api;
  }

  global.NcurveEditor = {create, highlightLine};
})(window);
