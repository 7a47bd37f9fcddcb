// Robot icons by kind (drawn here as SVG; no image files, no fonts).

const NS = 'http://www.w3.org/2000/svg';

const SHAPES: Record<string, string> = {
  // A base, two links and a wrist.
  arm: 'M10 54h28v-6H10zM18 48l4-18 18-12 8 6-16 10-4 14zM44 20l8-6 4 6-8 6z',
  // A round base with a sensor on top.
  mobile: 'M8 40a24 10 0 0 0 48 0v-8a24 10 0 0 0-48 0zM26 18h12v10H26z M14 50a4 4 0 1 0 8 0a4 4 0 1 0-8 0M42 50a4 4 0 1 0 8 0a4 4 0 1 0-8 0',
  // An arm on a wheeled base.
  mobile_manipulator: 'M6 44h40v8H6zM10 56a4 4 0 1 0 8 0a4 4 0 1 0-8 0M34 56a4 4 0 1 0 8 0a4 4 0 1 0-8 0M20 44l4-16 16-10 6 5-14 9-4 12zM42 20l7-5 4 5-7 5z',
  gripper: 'M28 8h8v20h-8zM18 28h28v8H18zM18 36h6v18h-6zM40 36h6v18h-6z',
};

export function robotIcon(kind: string): SVGSVGElement {
  const svg = document.createElementNS(NS, 'svg');
  svg.setAttribute('viewBox', '0 0 64 64');
  svg.setAttribute('class', 'icon');
  svg.setAttribute('aria-hidden', 'true');
  const key = kind.includes('manip') ? 'mobile_manipulator' : kind.includes('mobile') || kind.includes('base') ? 'mobile' : kind.includes('grip') ? 'gripper' : 'arm';
  const path = document.createElementNS(NS, 'path');
  path.setAttribute('d', SHAPES[key] ?? SHAPES.arm ?? '');
  svg.append(path);
  return svg;
}
