// Page 8: exercises. The reader's steps are applied by the engine; each goal is a predicate over
// the meshes after every step. The figure shows the reader's last attempt.
import { startPage } from './page.js';
import { createFigure, meshAfter, stagesFromSteps } from './figure.js';
import { EXERCISES, parseSteps, checkExercise } from './exercises.js';

function exerciseCard(ex, onCheck) {
  const card = document.createElement('section');
  card.className = 'exercise';
  card.dataset.exercise = ex.id;
  card.innerHTML = `<h2></h2><p class="goal"></p><label>Your steps<textarea spellcheck="false"></textarea></label>
    <div class="picker"><button type="button" data-do="check">Check</button><button type="button" data-do="answer">Show an answer</button>
    <span class="result" aria-live="polite"></span></div><details><summary>Hints</summary><ul></ul></details>`;
  card.querySelector('h2').textContent = ex.title;
  card.querySelector('.goal').textContent = ex.goal;
  for (const h of ex.hints) card.querySelector('ul').append(Object.assign(document.createElement('li'), { textContent: h }));
  const text = card.querySelector('textarea');
  text.setAttribute('aria-label', `steps for: ${ex.title}`);
  card.querySelector('[data-do=check]').addEventListener('click', () => onCheck(ex, text.value, card));
  card.querySelector('[data-do=answer]').addEventListener('click', () => {
    text.value = ex.answer.join('\n');
    onCheck(ex, text.value, card);
  });
  return card;
}

startPage(() => {
  const box = document.getElementById('exercises');
  let fig = null;
  const check = (ex, text, card) => {
    const out = card.querySelector('.result');
    const steps = parseSteps(text);
    const verdict = checkExercise(ex, steps, meshAfter);
    out.textContent = verdict.message;
    out.className = `result ${verdict.ok ? 'check-ok' : 'check-no'}`;
    card.dataset.solved = String(verdict.ok);
    const applied = steps.slice(0, verdict.applied);
    fig?.destroy();
    const host = document.getElementById('fig-try');
    card.append(host); // the result right under the exercise it answers
    fig = createFigure(host, {
      title: `your steps: ${ex.title}`,
      mesh: ex.mesh,
      stages: stagesFromSteps(applied),
      start: applied.length,
      sheetChips: true,
      sheet: (f) => f.mesh.sheets.find((s) => s.topology === 'sphere')?.id,
      caption: `${ex.title}: ${applied.length} step${applied.length === 1 ? '' : 's'} applied.`,
    });
  };
  for (const ex of EXERCISES) box.append(exerciseCard(ex, check));
  fig = createFigure(document.getElementById('fig-try'), {
    title: 'the first exercise’s mesh',
    mesh: EXERCISES[0].mesh,
    stages: stagesFromSteps([]),
    sheetChips: true,
    caption: 'Check an exercise to see your steps here.',
  });
});
