// Stable colours per sheet or chord id (golden-angle hues), so colours never jump between views.
export function colorFor(id) {
  const hue = (id * 137.508) % 360;
  return `hsl(${hue.toFixed(1)}, 65%, 55%)`;
}
