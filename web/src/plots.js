// The report's gnuplot PNGs beside the 3D view, with the time cursor: gnuplot wrote each plot's
// axes (<plot>.axes.jsonl: the plot area in pixels and its data range) when it drew it, so a
// time plot gets a vertical line at the current time in each of its panels and path.png a dot at
// the robot's (x, y).
import { imageUrl, readText, reportPath } from './data.js';

async function readAxes(path) {
  const text = await readText(path);
  return text.split('\n').filter((l) => l.trim()).map((l) => JSON.parse(l));
}

export async function buildPlots(container, plots) {
  const views = [];
  for (const plot of plots) {
    const file = reportPath(plot.file);
    const figure = document.createElement('figure');
    figure.className = 'plot';
    const img = document.createElement('img');
    img.alt = file;
    img.src = imageUrl(file);
    const overlay = document.createElement('div');
    overlay.className = 'overlay';
    const caption = document.createElement('figcaption');
    caption.textContent = file;
    const frame = document.createElement('div');
    frame.className = 'frame';
    frame.append(img, overlay);
    figure.append(frame, caption);
    container.append(figure);
    const panels = plot.axes ? await readAxes(reportPath(plot.axes)) : [];
    const isMap = file === 'path.png';
    const marks = panels.map(() => {
      const mark = document.createElement('div');
      mark.className = isMap ? 'dot' : 'cursor';
      overlay.append(mark);
      return mark;
    });
    await new Promise((resolve) => {
      if (img.complete) resolve();
      img.onload = resolve;
      img.onerror = resolve;
    });
    views.push({ img, panels, marks, isMap });
  }
  return views;
}

// Moves the cursors to time t (s); (x, y) is the base position for path.png (m).
export function updatePlots(views, t, x, y) {
  for (const { img, panels, marks, isMap } of views) {
    const W = img.naturalWidth;
    const H = img.naturalHeight;
    if (!W || !H) continue;
    panels.forEach((p, i) => {
      const [left, right, bottom, top] = p.px;
      const fx = (v) => (left + (v - p.x[0]) / (p.x[1] - p.x[0]) * (right - left)) / W * 100;
      const fy = (v) => (H - (bottom + (v - p.y[0]) / (p.y[1] - p.y[0]) * (top - bottom))) / H * 100;
      const mark = marks[i];
      if (isMap) {
        mark.style.left = `${fx(x)}%`;
        mark.style.top = `${fy(y)}%`;
        return;
      }
      const inside = t >= p.x[0] && t <= p.x[1];
      mark.style.display = inside ? 'block' : 'none';
      mark.style.left = `${fx(t)}%`;
      mark.style.top = `${(H - top) / H * 100}%`;
      mark.style.height = `${(top - bottom) / H * 100}%`;
    });
  }
}
