import { describe, expect, it } from 'vitest';
import { EXPORT_FORMATS, exportFileName } from './export';

describe('exportFileName', () => {
  it('names the file after the curve with the format extension', () => {
    expect(exportFileName('rail', '3', 'step')).toBe('rail.step');
    expect(exportFileName('rail', '3', 'iges')).toBe('rail.igs');
    expect(exportFileName('rail', '3', 'json')).toBe('rail.json');
  });
  it('replaces characters a file system refuses and trims blanks', () => {
    expect(exportFileName(' a/b\\c:d*e?"f<g>h|i\u0001 ', '3', 'step')).toBe(
      'a_b_c_d_e__f_g_h_i_.step',
    );
    expect(exportFileName('Spline (1)', '3', 'step')).toBe('Spline (1).step');
  });
  it('falls back to the label for an empty name or one made of dots', () => {
    expect(exportFileName('', '7', 'iges')).toBe('curve-7.igs');
    expect(exportFileName('..', '7', 'json')).toBe('curve-7.json');
  });
  it('offers exactly JSON, STEP, IGES and DXF (no format the server does not write)', () => {
    expect(Object.keys(EXPORT_FORMATS).sort()).toEqual(['dxf', 'iges', 'json', 'step']);
  });
});
