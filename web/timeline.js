// The timeline: applied steps as a strip, back / forward / play, ←/→ keys (main.js), click a step to
// jump there. Steps after the current position are kept (greyed) until a new step replaces them.
import { revealInStrip } from './scrollStrip.js';
import { inverseText, qualityText } from './stepText.js';

export function createTimeline(root, actions) {
  root.innerHTML = `<button id="tl-start" title="start mesh">«</button><button id="tl-back" title="back (←)">◀</button>
    <button id="tl-play" title="play">▶︎ play</button><button id="tl-fwd" title="forward (→)">▶</button>
    <span class="pos" id="tl-pos"></span><ol id="tl-steps"></ol><span class="pos" id="tl-report"></span>`;
  const $ = (s) => root.querySelector(s);
  let playing = 0;
  $('#tl-start').addEventListener('click', () => actions.goTo(0));
  $('#tl-back').addEventListener('click', () => actions.back());
  $('#tl-fwd').addEventListener('click', () => actions.forward());
  $('#tl-play').addEventListener('click', () => {
    if (playing) return stop();
    const s = window.hexdual.store.get();
    if (s.at >= s.steps.length) actions.goTo(0);
    playing = setInterval(() => {
      const t = window.hexdual.store.get();
      if (t.at >= t.steps.length) return stop();
      actions.forward();
    }, 900);
    $('#tl-play').textContent = '⏸ pause';
  });
  function stop() {
    clearInterval(playing);
    playing = 0;
    $('#tl-play').textContent = '▶︎ play';
  }
  $('#tl-steps').addEventListener('click', (e) => {
    const li = e.target.closest('li[data-k]');
    if (li) actions.goTo(Number(li.dataset.k));
  });
  $('#tl-report').addEventListener('click', () => $('#tl-report').classList.toggle('full'));
  let shown = null;
  return {
    update(s) {
      const key = `${s.steps.join(';')}|${s.at}|${s.report?.key}`;
      if (key === shown) return;
      shown = key;
      $('#tl-pos').textContent = `step ${s.at} of ${s.steps.length}`;
      $('#tl-back').disabled = $('#tl-start').disabled = s.at === 0;
      $('#tl-fwd').disabled = s.at >= s.steps.length;
      $('#tl-play').disabled = s.steps.length === 0;
      const start = Object.assign(document.createElement('li'), { textContent: 'start' });
      start.dataset.k = '0';
      if (s.at === 0) start.classList.add('current');
      $('#tl-steps').replaceChildren(
        start,
        ...s.steps.map((step, i) => {
          const li = document.createElement('li');
          li.textContent = `${i + 1}. ${step}`;
          li.dataset.k = String(i + 1);
          li.classList.add(i < s.at ? 'done' : 'future');
          if (i + 1 === s.at) li.classList.add('current');
          return li;
        }),
      );
      const r = s.report && s.report.key === s.meshKey ? s.report : null;
      const part = (t) => (t ? ` · ${t}` : '');
      $('#tl-report').textContent = r
        ? `${r.step}: +${r.created.length} / −${r.removed.length} hexes${part(qualityText(r.quality))}${part(inverseText(r))} · sheets ${r.changedSheets.join(', ') || '–'} · chords ${r.changedChords.slice(0, 8).join(', ') || '–'}${r.changedChords.length > 8 ? ' …' : ''}`
        : '';
      $('#tl-report').title = r && r.inverse ? $('#tl-report').textContent.replace(inverseText(r), inverseText(r, { full: true })) : $('#tl-report').textContent;
      revealInStrip($('#tl-steps'), $('#tl-steps .current'));
    },
  };
}
