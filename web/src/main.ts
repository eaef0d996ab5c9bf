// Entry point: open the document named in the address
// (#doc=NAME, default workbench.hula) and expose window.__hula for tests.

import './style.css';
import { App, waitIdle } from './app';
import { Client } from './api/client';

declare global {
  interface Window {
    __hula: {
      app: App;
      idle(): Promise<void>;
      ready: Promise<void>;
    };
  }
}

// Authorised by the cookie `hula serve` sets when the page is opened with ?token=.
const client = new Client(location.origin);
const hash = new URLSearchParams(location.hash.slice(1));
const docName = hash.get('doc') ?? 'workbench.hula';
// The document is fetched while the views (WebGL) are built: first load waits for the slower, not both.
const prefetched = client.getDocument(docName);
prefetched.catch(() => undefined); // open() reports the failure
const app = new App(client, docName);
const ready = app.open(docName, prefetched).catch((e: unknown) => {
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
