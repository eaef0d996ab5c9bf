// The toolbar's Export menu: the selected curve written by the server as a
// JSON curve file, a STEP (AP214), an IGES 5.3 or a DXF (SPLINE) file, and downloaded under
// the curve's name. The page never writes a format itself.

import type { ExportFormat } from '../api/types';

/** The formats the menu offers, with the file extension and MIME type of each download. */
export const EXPORT_FORMATS = {
  json: { extension: 'json', mime: 'application/json' },
  step: { extension: 'step', mime: 'model/step' },
  iges: { extension: 'igs', mime: 'model/iges' },
  dxf: { extension: 'dxf', mime: 'image/vnd.dxf' },
} as const satisfies Partial<Record<ExportFormat, { extension: string; mime: string }>>;
export type MenuFormat = keyof typeof EXPORT_FORMATS;

/**
 * The download's file name: the curve's name with the format's extension, characters a file
 * system refuses (separators, control characters, reserved punctuation) replaced by '_'; the
 * label when the name is empty or only dots.
 */
export function exportFileName(name: string, label: string, format: MenuFormat): string {
  // eslint-disable-next-line no-control-regex
  let stem = name.trim().replace(/[\u0000-\u001f\u007f/\\:*?"<>|]/g, '_');
  if (/^\.*$/.test(stem)) stem = `curve-${label}`;
  return `${stem}.${EXPORT_FORMATS[format].extension}`;
}

/** Offers `text` as a file download named `filename`. */
export function download(text: string, filename: string, mime: string): void {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([text], { type: mime }));
  a.download = filename;
  a.click();
  URL.revokeObjectURL(a.href);
}

/**
 * The drop-down under the Export button: opened by the button or key E (focus on its first item),
 * an item (or its key J, S, I, D) runs `choose`; Escape, a click elsewhere or a choice closes it.
 */
export class ExportMenu {
  private readonly button: HTMLButtonElement;
  private readonly menu: HTMLElement;

  constructor(private readonly choose: (format: MenuFormat) => void) {
    this.button = document.getElementById('export-button') as HTMLButtonElement;
    this.menu = document.getElementById('export-menu')!;
    document.addEventListener('pointerdown', (ev) => {
      if (this.isOpen && !this.button.parentElement!.contains(ev.target as Node)) this.close();
    });
    this.menu.addEventListener('keydown', (ev) => {
      const keys: Record<string, MenuFormat> = { j: 'json', s: 'step', i: 'iges', d: 'dxf' };
      const k = ev.key.toLowerCase();
      const items = [...this.menu.querySelectorAll<HTMLButtonElement>('button')];
      const at = items.indexOf(document.activeElement as HTMLButtonElement);
      if (keys[k]) this.pick(keys[k]);
      else if (k === 'escape') {
        this.close();
        this.button.focus();
      } else if (k === 'arrowdown') items[(at + 1) % items.length]!.focus();
      else if (k === 'arrowup') items[(at + items.length - 1) % items.length]!.focus();
      else return;
      ev.preventDefault();
      ev.stopPropagation();
    });
  }

  get isOpen(): boolean {
    return !this.menu.hidden;
  }

  toggle(): void {
    if (this.isOpen) this.close();
    else this.open();
  }

  open(): void {
    this.menu.hidden = false;
    this.button.setAttribute('aria-expanded', 'true');
    this.menu.querySelector<HTMLButtonElement>('button')!.focus();
  }

  close(): void {
    this.menu.hidden = true;
    this.button.setAttribute('aria-expanded', 'false');
  }

  pick(format: MenuFormat): void {
    this.close();
    this.choose(format);
  }
}
