// A small DevTools-protocol client for headless Chromium on Node's WebSocket (Node 20:
// `node --experimental-websocket`): one page, its console errors collected. Used by
// scripts/web-test.mjs and scripts/web-bench.mjs; no browser or client is downloaded.
import { spawn } from 'node:child_process';
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

export const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// Starts `chromium` headless (software WebGL) and opens one page. `downloads`: where the
// page's downloads go.
export async function launch(chromium, downloads) {
  const profile = mkdtempSync(join(tmpdir(), 'fixstep-web-'));
  const browser = spawn(chromium, [
    '--headless', '--no-sandbox', '--hide-scrollbars', '--window-size=1000,700',
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
    '--no-first-run', '--no-default-browser-check', `--user-data-dir=${profile}`,
    '--remote-debugging-port=0', 'about:blank',
  ], { stdio: ['ignore', 'ignore', 'pipe'] });
  const endpoint = await new Promise((resolve, reject) => {
    let text = '';
    browser.stderr.on('data', (chunk) => {
      text += chunk;
      const match = text.match(/DevTools listening on (ws:\/\/\S+)/);
      if (match) resolve(match[1]);
    });
    browser.on('exit', (code) => reject(new Error(`chromium exited (${code}): ${text}`)));
    setTimeout(() => reject(new Error(`no DevTools endpoint: ${text}`)), 30000);
  });

  // Numbered requests, answered by id; events to the listeners.
  const socket = new WebSocket(endpoint);
  await new Promise((resolve) => socket.addEventListener('open', resolve));
  let next = 0;
  const waiting = new Map();
  const listeners = [];
  socket.addEventListener('message', ({ data }) => {
    const message = JSON.parse(data);
    if (message.id !== undefined) {
      const { resolve, reject } = waiting.get(message.id);
      waiting.delete(message.id);
      message.error ? reject(new Error(JSON.stringify(message.error))) : resolve(message.result);
    } else {
      for (const listener of listeners) listener(message);
    }
  });
  const send = (method, params = {}, sessionId) => new Promise((resolve, reject) => {
    const id = ++next;
    waiting.set(id, { resolve, reject });
    socket.send(JSON.stringify({ id, method, params, sessionId }));
  });

  const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await send('Target.attachToTarget', { targetId, flatten: true });
  const page = (method, params) => send(method, params, sessionId);
  const errors = [];
  listeners.push(({ method, params }) => {
    if (method === 'Runtime.exceptionThrown') {
      errors.push(`uncaught: ${params.exceptionDetails.exception?.description ?? params.exceptionDetails.text}`);
    } else if (method === 'Runtime.consoleAPICalled' && ['error', 'assert'].includes(params.type)) {
      errors.push(`console.${params.type}: ${params.args.map((a) => a.value ?? a.description).join(' ')}`);
    } else if (method === 'Log.entryAdded' && params.entry.level === 'error') {
      errors.push(`log: ${params.entry.text} ${params.entry.url ?? ''}`);
    }
  });
  await page('Runtime.enable');
  await page('Log.enable');
  await page('Page.enable');
  if (downloads) await send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: downloads });

  // The value of a JavaScript expression in the page (promises awaited).
  const evaluate = async (expression) => {
    const { result, exceptionDetails } = await page('Runtime.evaluate', {
      expression, awaitPromise: true, returnByValue: true,
    });
    if (exceptionDetails) throw new Error(`${expression}: ${exceptionDetails.exception?.description}`);
    return result.value;
  };
  // Waits until `expression` is true in the page.
  const until = async (expression, seconds, what) => {
    for (const end = Date.now() + seconds * 1000; Date.now() < end; await sleep(50)) {
      if (await evaluate(expression)) return;
    }
    throw new Error(`timed out after ${seconds} s waiting for ${what}`);
  };
  return { page, evaluate, until, errors, close: () => browser.kill() };
}
