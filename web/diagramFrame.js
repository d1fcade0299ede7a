// The square a sheet diagram is framed in (diagram units, y up): a disk drawn in the shape its
// quads give (a long rectangle, a square) is framed by its outer loop's box, so it fills the panel;
// local views keep their dotted unit circle, opened spheres the room outside it for the opened hex.
// `area`: what the crossings spread over, with the frame's margin (the outer loop's area x 1.15²);
// `hx`, `hy`: half the box's width and height with the margin (a panel of another shape fits those);
// `right`: the outer loop's right side (labels there go to the left of their crossings).
export function diagramFrame(d) {
  const loop = d.loops?.[0] ?? [];
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity, twice = 0;
  loop.forEach(([x, y], i) => {
    const [nx, ny] = loop[(i + 1) % loop.length];
    twice += x * ny - nx * y;
    x0 = Math.min(x0, x); x1 = Math.max(x1, x);
    y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  });
  const right = loop.length > 0 ? x1 : 1;
  const opened = d.openedHex !== null && d.openedHex !== undefined;
  if (opened) return { cx: 0, cy: 0, half: 1.6, hx: 1.6, hy: 1.6, area: Math.PI * 1.6 * 1.6, right };
  if (d.local || loop.length < 3) return { cx: 0, cy: 0, half: 1.15, hx: 1.15, hy: 1.15, area: Math.PI * 1.15 * 1.15, right };
  const margin = 0.075 * Math.max(x1 - x0, y1 - y0, 0.2);
  return {
    cx: (x0 + x1) / 2, cy: (y0 + y1) / 2,
    half: (1.15 * Math.max(x1 - x0, y1 - y0, 0.2)) / 2,
    hx: (x1 - x0) / 2 + margin, hy: (y1 - y0) / 2 + margin,
    area: Math.max((1.3225 * Math.abs(twice)) / 2, 0.01),
    right,
  };
}
