import { describe, expect, it } from 'vitest';
import { coordinateText } from './panels';

describe('coordinateText', () => {
  it('shows rounding noise of a planar curve as 0, relative to the curve size', () => {
    expect(coordinateText(3.00708e-15, 120)).toBe('0');
    expect(coordinateText(-4e-13, 1000)).toBe('0');
    // A small but real coordinate of a small curve is kept.
    expect(coordinateText(3e-4, 1)).toBe('0.0003');
    expect(coordinateText(2.5e-11, 1)).toBe('2.5e-11');
  });
  it('keeps at most 12 significant digits and round numbers exact', () => {
    expect(coordinateText(0.1 + 0.2, 1)).toBe('0.3');
    expect(coordinateText(120, 120)).toBe('120');
    expect(coordinateText(-40, 120)).toBe('-40');
    expect(coordinateText(1 / 3, 1)).toBe('0.333333333333');
  });
});
