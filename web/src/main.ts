// Entry point: take the token, open the document named in the address
// (#doc=NAME, default workbench.hula) and expose window.__hula for tests.

import './style.css';
import { App, waitIdle } from './app';
import { Client, takeToken } from './api/client';

declare global {
  interface Window {
    __hula: {
      app: App;
      idle(): Promise<void>;
      ready: Promise<void>;
    };
  }
}

const token = takeToken(location, sessionStorage, history);
const client = new Client(location.origin, token);
const hash = new URLSearchParams(location.hash.slice(1));
const docName = hash.get('doc') ?? 'workbench.hula';
const app = new App(client, docName);
const ready = app.open(docName).catch((e: unknown) => {
  app.toast(e);
});
window.__hula = {
  app,
  ready,
  idle: async () => {
    await ready;
    await waitIdle(app);
  },
};
