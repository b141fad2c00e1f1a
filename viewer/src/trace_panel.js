// A tree run's trace (`antipode run --trace`), replayed as Groot2 replays a log: the tree as
// nested boxes, each node with its status at the chosen step and how long its last run took;
// a slider steps through every status change, and buttons jump to the previous or next
// failure.

import { element } from './dom.js';

/**
 * The status of every node after event `step` of `trace`, and how long each took last:
 * {status[], took_s[]}. A trace records no return to IDLE, so a node that starts again
 * (leaves IDLE) sets its descendants back to IDLE. A node that went from IDLE straight to its
 * end took the time since the event before; one that ran took the time since it started.
 */
export function statesAt(trace, step) {
  const n = trace.nodes.length;
  const status = new Array(n).fill('IDLE');
  const took = new Array(n).fill(NaN);
  const started = new Array(n).fill(0);
  const children = childrenOf(trace);
  const reset = (node) => {
    for (const child of children[node]) {
      status[child] = 'IDLE';
      reset(child);
    }
  };
  for (let k = 0; k <= step && k < trace.events.length; k++) {
    const [time, node, from, to] = trace.events[k];
    const name = trace.statuses[to];
    if (trace.statuses[from] === 'IDLE') {
      reset(node);
      started[node] = k > 0 ? trace.events[k - 1][0] : 0;
    }
    status[node] = name;
    took[node] = name === 'SUCCESS' || name === 'FAILURE' ? time - started[node] : NaN;
  }
  return { status, took };
}

const childrenCache = new WeakMap();
function childrenOf(trace) {
  if (!childrenCache.has(trace)) {
    const children = trace.nodes.map(() => []);
    trace.nodes.forEach((node, i) => node.parent >= 0 && children[node.parent].push(i));
    childrenCache.set(trace, children);
  }
  return childrenCache.get(trace);
}

/** Builds the trace's diagram and slider into `root`. Returns {step(k)} for the test hook. */
export function buildTracePanel(root, trace) {
  root.appendChild(element('h2', {}, trace.file));
  const controls = root.appendChild(element('div', { class: 'trace-controls' }));
  const back = controls.appendChild(element('button', { id: 'trace-previous-failure' }, '◀ failure'));
  const slider = controls.appendChild(
    element('input', { id: 'trace-step', type: 'range', min: 0, max: trace.events.length - 1, value: trace.events.length - 1 }),
  );
  const next = controls.appendChild(element('button', { id: 'trace-next-failure' }, 'failure ▶'));
  const caption = root.appendChild(element('p', { id: 'trace-caption' }));
  const tree = root.appendChild(element('div', { id: 'trace-tree' }));

  // The diagram: one box per node inside its parent's.
  const boxes = trace.nodes.map((node, i) => {
    const box = element('div', { class: 'node', 'data-node': i, title: node.where || node.path });
    box.appendChild(element('span', { class: 'label' }));
    return box;
  });
  trace.nodes.forEach((node, i) => (node.parent >= 0 ? boxes[node.parent] : tree).appendChild(boxes[i]));

  const failure = trace.statuses.indexOf('FAILURE');
  function step(k) {
    slider.value = k;
    const { status, took } = statesAt(trace, k);
    const [time, node, , to, reason] = trace.events[k];
    trace.nodes.forEach((n, i) => {
      boxes[i].dataset.status = status[i];
      const ms = !Number.isFinite(took[i]) ? '' : `${status[i] === 'IDLE' ? ', last run' : ''} ${(took[i] * 1000).toFixed(1)} ms`;
      boxes[i].firstChild.textContent = `${n.name}${n.type && n.type !== n.name ? ' (' + n.type + ')' : ''}: ${status[i]}${ms}`;
      boxes[i].classList.toggle('changed', i === node);
    });
    caption.textContent =
      `step ${k + 1} of ${trace.events.length}, ${time.toFixed(3)} s: ${trace.nodes[node].name} → ${trace.statuses[to]}` +
      (reason >= 0 ? ` (${trace.reasons[reason]})` : '');
  }
  const seek = (from, direction) => {
    for (let k = from + direction; k >= 0 && k < trace.events.length; k += direction)
      if (trace.events[k][3] === failure) return step(k);
  };
  slider.addEventListener('input', () => step(Number(slider.value)));
  back.addEventListener('click', () => seek(Number(slider.value), -1));
  next.addEventListener('click', () => seek(Number(slider.value), 1));
  step(trace.events.length - 1);
  return { step, caption };
}
