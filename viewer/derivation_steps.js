// An L-system's derivation step by step (fgsg view --steps): a slider from 0 (the axiom)
// to the derivation's length and a Play button that moves it one step each time the
// step asked for has been shown, stopping at the length. Each move sends
// {"type":"set","step":N}; the server derives that step, or takes it from the steps it
// has kept (cli/view_session.h). The model's header says which step it is and the
// length ("steps"); a model without it (no --steps, no L-system) hides the slider.
// state.steps is what the browser tests read: {step, length, shown: [steps in order]}.
export function createDerivationSteps(ctx) {
  const { state } = ctx;
  const $ = (id) => document.getElementById(id);
  const box = $('steps'), slider = $('step-slider'), label = $('step-label'), play = $('step-play');
  const playDelayMs = 400;  // how long each step stays in view while playing
  let playing = false;

  function ask(step) {
    label.textContent = `${step} / ${slider.max}`;
    ctx.send({ type: 'set', step });
  }
  function setPlaying(on) {
    playing = on;
    play.textContent = on ? 'Pause' : 'Play';
    play.classList.toggle('on', on);
  }
  slider.addEventListener('input', () => {
    setPlaying(false);
    ask(Number(slider.value));
  });
  play.addEventListener('click', () => {
    if (playing) return setPlaying(false);
    setPlaying(true);
    // From the start again when the last step is shown.
    ask(Number(slider.value) >= Number(slider.max) ? 0 : Number(slider.value) + 1);
  });

  return {
    // A model was shown: `steps` is its header's {step, length}, or undefined.
    shown(steps) {
      if (!steps) {
        box.hidden = true;
        state.steps = null;
        setPlaying(false);
        return;
      }
      box.hidden = false;
      slider.max = steps.length;
      slider.value = steps.step;
      label.textContent = `${steps.step} / ${steps.length}`;
      const shownBefore = state.steps ? state.steps.shown : [];
      state.steps = { step: steps.step, length: steps.length, shown: shownBefore.concat([steps.step]) };
      if (!playing) return;
      if (steps.step >= steps.length) return setPlaying(false);
      setTimeout(() => { if (playing) ask(steps.step + 1); }, playDelayMs);
    },
    // The server refused a message of the page's: a step past a changed length, say.
    refused() { setPlaying(false); },
  };
}
