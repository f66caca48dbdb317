// How smoothly a replay page (docs/replay.md) plays in headless Chromium: opens the page, lets it
// play for a few seconds of real time and prints the frames per second the page measured with
// requestAnimationFrame (window.multicpgReplay.measureFps). A measurement for
// docs/benchmarks.md, not a test.
//
//   node --experimental-websocket bench/bench_replay.mjs PAGE.html [SECONDS] [WIDTHxHEIGHT]
//
// Node 20's own WebSocket speaks the DevTools protocol to Chromium: no package is needed.
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

const [page, seconds = '5', size = '1280x800'] = process.argv.slice(2);
if (!page) {
  console.error('usage: bench_replay.mjs PAGE.html [SECONDS] [WIDTHxHEIGHT]');
  process.exit(2);
}
const profile = mkdtempSync(join(tmpdir(), 'bench-replay-'));
const chromium = spawn('chromium', [
  '--headless', '--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--disable-quic',
  '--no-first-run', '--disable-background-networking', '--disable-component-update',
  '--disable-sync', '--remote-debugging-port=0', `--user-data-dir=${profile}`,
  `--window-size=${size.replace('x', ',')}`, 'about:blank',
], { stdio: ['ignore', 'ignore', 'pipe'] });

// Chromium prints "DevTools listening on ws://..." when its protocol is ready.
const endpoint = await new Promise((done, failed) => {
  let text = '';
  chromium.stderr.on('data', (chunk) => {
    text += chunk;
    const m = /DevTools listening on (ws:\S+)/.exec(text);
    if (m) done(m[1]);
  });
  chromium.once('exit', () => failed(new Error('chromium ended: ' + text)));
});

const browser = new WebSocket(endpoint);
await new Promise((done) => browser.addEventListener('open', done));
let next = 0;
const waiting = new Map();
browser.addEventListener('message', (m) => {
  const reply = JSON.parse(m.data);
  if (waiting.has(reply.id)) {
    waiting.get(reply.id)(reply);
    waiting.delete(reply.id);
  }
});
function send(method, params = {}, sessionId = undefined) {
  const id = ++next;
  browser.send(JSON.stringify({ id, method, params, sessionId }));
  return new Promise((done) => waiting.set(id, done));
}

const { result: { targetId } } = await send('Target.createTarget', { url: 'about:blank' });
const { result: { sessionId } } = await send('Target.attachToTarget', { targetId, flatten: true });
const evaluate = async (expression) => {
  const reply = await send('Runtime.evaluate', { expression, awaitPromise: true, returnByValue: true },
    sessionId);
  if (reply.result.exceptionDetails) throw new Error(JSON.stringify(reply.result.exceptionDetails));
  return reply.result.result.value;
};
const started = Date.now();
await send('Page.navigate', { url: 'file://' + resolve(page) }, sessionId);
while (!(await evaluate("document.body && document.body.dataset.replay === 'ready'"))) {
  await new Promise((done) => setTimeout(done, 50));
}
const loadMs = Date.now() - started;
const info = await evaluate('({steps: multicpgReplay.lastStep - multicpgReplay.firstStep, ' +
  'errors: window.multicpgErrors, width: innerWidth, height: innerHeight})');
const fps = await evaluate(`multicpgReplay.measureFps(${Number(seconds) * 1000})`);
console.log(JSON.stringify({ page, steps: info.steps, viewport: `${info.width}x${info.height}`,
  load_ms: loadMs, fps: Math.round(fps * 10) / 10, errors: info.errors }));
browser.close();
const ended = new Promise((done) => chromium.on('exit', done));
chromium.kill();
await ended;
rmSync(profile, { recursive: true, force: true });
