// Scrolling a horizontal strip (the explorer's step chips, the puzzles' list on a phone) so that one
// of its items is in view, without moving the page or anything outside the strip as
// Element.scrollIntoView would.
export function revealInStrip(strip, item, margin = 4) {
  if (!item || strip.scrollWidth <= strip.clientWidth) return;
  const left = item.getBoundingClientRect().left - strip.getBoundingClientRect().left + strip.scrollLeft;
  const right = left + item.offsetWidth;
  if (left - margin < strip.scrollLeft) strip.scrollLeft = left - margin;
  else if (right + margin > strip.scrollLeft + strip.clientWidth) strip.scrollLeft = right + margin - strip.clientWidth;
}
