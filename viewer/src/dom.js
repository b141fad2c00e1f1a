// Small helpers to build the panels' elements.

/** A new element `tag` with `attributes` and text. */
export function element(tag, attributes = {}, text = '') {
  const e = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) e.setAttribute(key, value);
  if (text) e.textContent = text;
  return e;
}

/** A table of [key, value] rows into `table` (replacing its rows); rows carry data-key. */
export function factRows(table, facts) {
  table.replaceChildren();
  for (const [key, value] of facts) {
    const row = table.appendChild(element('tr', { 'data-key': key }));
    row.appendChild(element('th', {}, key));
    row.appendChild(element('td', {}, value));
  }
}

export const number = (v, digits = 4) => (typeof v === 'number' ? v.toFixed(digits) : String(v));
export const vector = (v) => (Array.isArray(v) ? '[' + v.map((x) => number(x)).join(', ') + ']' : '-');

/** The cell's record of an attempt as [key, value] rows, lists joined and empty ones left out. */
export function recordFacts(record) {
  const facts = [];
  for (const [key, value] of Object.entries(record || {})) {
    if (value === null || value === '' || (Array.isArray(value) && value.length === 0)) continue;
    facts.push([key, Array.isArray(value) ? value.join(', ') : typeof value === 'number' ? number(value) : String(value)]);
  }
  return facts;
}
