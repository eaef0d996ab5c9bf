import { describe, expect, it } from 'vitest';
import { keyCommand, type KeyPress } from './keys';

const press = (key: string, mods: Partial<KeyPress> = {}): KeyPress => ({
  key,
  ctrlKey: false,
  metaKey: false,
  altKey: false,
  shiftKey: false,
  ...mods,
});

describe('the keyboard map', () => {
  it('undoes with Ctrl+Z (or ⌘Z) and redoes with Ctrl+Shift+Z and Ctrl+Y', () => {
    expect(keyCommand(press('z', { ctrlKey: true }))).toEqual({ kind: 'undo' });
    expect(keyCommand(press('Z', { metaKey: true }))).toEqual({ kind: 'undo' });
    expect(keyCommand(press('Z', { ctrlKey: true, shiftKey: true }))).toEqual({ kind: 'redo' });
    expect(keyCommand(press('y', { ctrlKey: true }))).toEqual({ kind: 'redo' });
  });

  it('leaves other Ctrl, ⌘ and Alt chords to the browser', () => {
    expect(keyCommand(press('s', { ctrlKey: true }))).toBeNull();
    expect(keyCommand(press('x', { altKey: true }))).toBeNull();
    expect(keyCommand(press('c', { metaKey: true }))).toBeNull();
  });

  it('maps the single keys of the help dialog, either case', () => {
    expect(keyCommand(press('S'))).toEqual({ kind: 'tool', tool: 'spline' });
    expect(keyCommand(press('v'))).toEqual({ kind: 'tool', tool: 'select' });
    expect(keyCommand(press('Delete'))).toEqual({ kind: 'action', action: 'delete' });
    expect(keyCommand(press('Backspace'))).toEqual({ kind: 'action', action: 'delete' });
    expect(keyCommand(press('x'))).toEqual({ kind: 'action', action: 'split' });
    expect(keyCommand(press('?', { shiftKey: true }))).toEqual({ kind: 'action', action: 'help' });
    expect(keyCommand(press('3'))).toEqual({ kind: 'view', view: 'side' });
    expect(keyCommand(press('g'))).toEqual({ kind: 'grid-snap' });
    expect(keyCommand(press('G', { shiftKey: true }))).toEqual({ kind: 'object-snap' });
    expect(keyCommand(press('r'))).toEqual({ kind: 'navigate', mode: 'orbit' });
    expect(keyCommand(press('Escape'))).toEqual({ kind: 'escape' });
    expect(keyCommand(press('M'))).toEqual({ kind: 'tool', tool: 'match' });
    expect(keyCommand(press('j'))).toEqual({ kind: 'tool', tool: 'blend' });
    expect(keyCommand(press('c'))).toEqual({ kind: 'action', action: 'close' });
    expect(keyCommand(press('R', { shiftKey: true }))).toEqual({
      kind: 'action',
      action: 'rebuild',
    });
    expect(keyCommand(press('O', { shiftKey: true }))).toEqual({
      kind: 'action',
      action: 'offset',
    });
    expect(keyCommand(press('C', { shiftKey: true }))).toEqual({
      kind: 'action',
      action: 'clothoid',
    });
    expect(keyCommand(press('I', { shiftKey: true }))).toEqual({ kind: 'tool', tool: 'intersect' });
    expect(keyCommand(press('K', { shiftKey: true }))).toEqual({ kind: 'tool', tool: 'knots' });
    expect(keyCommand(press('i'))).toEqual({ kind: 'action', action: 'import' });
    expect(keyCommand(press('k'))).toEqual({ kind: 'action', action: 'natural' });
    expect(keyCommand(press('o'))).toEqual({ kind: 'action', action: 'open' });
    expect(keyCommand(press('t'))).toBeNull();
    expect(keyCommand(press('F5'))).toBeNull();
  });
});
