// What the workbench's scripts share: an element with its class and text (always as text, never
// markup), and a number as the page writes it (at most `digits` decimals, 3 by default, no trailing 0).
(function (global) {
  'use strict';
  const el = (tag, cls, text) => {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    return e;
  };
  const fmt = (v, digits) => (Math.abs(v) < 1e-12 ? 0 : v).toFixed(digits === undefined ? 3 : digits).replace(/(\.\d*?)0+$/, '$1').replace(/\.$/, '') || '0';
  global.NcurveDom = {el, fmt};
})(window);
