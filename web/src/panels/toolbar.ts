// The toolbar and the keyboard: each button, toggle and key press turned
// into the App's command (controller/keys.ts maps the keys).

import type { App } from '../app';
import { keyCommand } from '../controller/keys';
import type { ToolName } from '../tools/tools';
import type { MenuFormat } from './export';

export class Toolbar {
  constructor(private readonly app: App) {}

  /** Listen to the toolbar's buttons and toggles, the import file input and the keyboard. */
  bind(): void {
    for (const b of document.querySelectorAll<HTMLButtonElement>('[data-tool]')) {
      b.addEventListener('click', () => {
        this.app.setTool(b.dataset['tool'] as ToolName);
      });
    }
    for (const b of document.querySelectorAll<HTMLButtonElement>('[data-action]')) {
      b.addEventListener('click', () => {
        this.action(b.dataset['action']!);
      });
    }
    const snap = document.getElementById('snap') as HTMLInputElement;
    snap.addEventListener('change', () => {
      this.app.setSnap(snap.checked);
    });
    const continuity = document.getElementById('join-continuity') as HTMLSelectElement;
    continuity.addEventListener('change', () => {
      this.app.setJoinContinuity(Number(continuity.value));
    });
    const osnap = document.getElementById('osnap') as HTMLInputElement;
    osnap.addEventListener('change', () => {
      this.app.setObjectSnap(osnap.checked);
    });
    document.getElementById('import-file')!.addEventListener('change', (ev) => {
      const input = ev.target as HTMLInputElement;
      const file = input.files?.[0];
      input.value = '';
      if (file) void this.app.importFile(file);
    });
    window.addEventListener('keydown', (ev) => {
      this.key(ev);
    });
  }

  action(name: string): void {
    switch (name) {
      case 'undo':
        void this.app.undo();
        break;
      case 'redo':
        void this.app.redo();
        break;
      case 'delete':
        void this.app.deleteSelected();
        break;
      case 'insert-knot':
        void this.app.insertKnotSelected();
        break;
      case 'elevate':
        void this.app.elevateSelected();
        break;
      case 'split':
        void this.app.splitSelected();
        break;
      case 'reverse':
        void this.app.reverseSelected();
        break;
      case 'rebuild':
        this.app.panels.rebuildDialog();
        break;
      case 'close':
        void this.app.closeSelected();
        break;
      case 'offset':
        this.app.panels.offsetDialog();
        break;
      case 'clothoid':
        // Through the selected curve's points (a dialog), else through clicked points (a tool).
        if (this.app.selected) this.app.panels.clothoidDialog();
        else this.app.setTool('clothoid');
        break;
      case 'fit':
        this.app.fitAll();
        break;
      case 'layout':
        this.app.setLayout(this.app.viewports.layout === 'quad' ? 'single' : 'quad');
        break;
      case 'law':
        this.app.panels.lawDialog();
        break;
      case 'natural':
        this.app.panels.naturalDialog();
        break;
      case 'import':
        document.getElementById('import-file')!.click();
        break;
      case 'open':
        void this.app.panels.openDialog();
        break;
      case 'export':
        this.app.exportMenu.toggle();
        break;
      case 'export-json':
      case 'export-step':
      case 'export-iges':
      case 'export-dxf':
        this.app.exportMenu.pick(name.slice('export-'.length) as MenuFormat);
        break;
      case 'help':
        this.app.panels.helpDialog();
        break;
      case 'accept-fairing':
        void this.app.fairing.accept();
        break;
    }
  }

  /** A key press: a dialog or text field keeps it, the tool in use sees it first, then the map. */
  key(ev: KeyboardEvent): void {
    // A dialog owns the keyboard (Escape closes it natively).
    if ((document.getElementById('dialog') as HTMLDialogElement).open) return;
    const target = ev.target as HTMLElement | null;
    if (
      target &&
      (target.tagName === 'INPUT' || target.tagName === 'TEXTAREA' || target.tagName === 'SELECT')
    )
      return;
    if (this.app.tool?.key(ev)) {
      ev.preventDefault();
      return;
    }
    const c = keyCommand(ev);
    if (!c) return;
    ev.preventDefault();
    switch (c.kind) {
      case 'undo':
        void this.app.undo();
        break;
      case 'redo':
        void this.app.redo();
        break;
      case 'tool':
        this.app.setTool(c.tool);
        break;
      case 'action':
        this.action(c.action);
        break;
      case 'view':
        this.app.setLayout('single', c.view);
        break;
      case 'object-snap':
        this.app.setObjectSnap(!this.app.objectSnap);
        this.app.setStatus(`Object snap ${this.app.objectSnap ? 'on' : 'off'} (Shift+G)`);
        break;
      case 'grid-snap':
        this.app.setSnap(!this.app.viewports.snap);
        this.app.setStatus(`Grid snap ${this.app.viewports.snap ? 'on' : 'off'} (G)`);
        break;
      case 'navigate':
        this.app.input.navMode = this.app.input.navMode === c.mode ? null : c.mode;
        break;
      case 'escape':
        this.app.input.navMode = null;
        if (this.app.ghost) this.app.setGhost(null);
        else this.app.select(null);
        break;
    }
  }
}
