// Opens the browser testbed in headless Chromium in real time (no virtual clock) through the
// DevTools protocol on a pipe, lets a scene run, and prints what the page's cost panel says; with
// --screenshot FILE it also saves a picture of the page. For docs/browser-testbed.md's frame
// costs and screenshot:
//   node web/tools/cdp_run.mjs SITE_DIR [--scene NAME] [--seconds S] [--screenshot FILE]
//                              [--joint N] (open joint N's panel)
import { spawn } from 'node:child_process';
import { writeFileSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : fallback;
};
const site = resolve(args[0]);
const scene = option('--scene', 'pendulum');
const seconds = Number(option('--seconds', '5'));
const screenshot = option('--screenshot', null);
const chromiumPath = option('--chromium', 'chromium');

const profile = mkdtempSync(join(tmpdir(), 'pivot-cdp-'));
const browser = spawn(chromiumPath, [
  '--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-sync',
  '--disable-background-networking', '--disable-component-update', '--remote-debugging-pipe',
  '--window-size=1300,960', `--user-data-dir=${profile}`, 'about:blank',
], { stdio: ['ignore', 'ignore', 'ignore', 'pipe', 'pipe'] });

const toBrowser = browser.stdio[3];
const fromBrowser = browser.stdio[4];
let nextId = 1;
const waiting = new Map();
let buffered = '';
fromBrowser.on('data', (chunk) => {
  buffered += chunk.toString();
  let end;
  while ((end = buffered.indexOf('\0')) >= 0) {
    const message = JSON.parse(buffered.slice(0, end));
    buffered = buffered.slice(end + 1);
    if (message.id && waiting.has(message.id)) {
      const { resolve: done, reject } = waiting.get(message.id);
      waiting.delete(message.id);
      if (message.error) reject(new Error(JSON.stringify(message.error)));
      else done(message.result);
    }
  }
});
const send = (method, params = {}, sessionId) => new Promise((done, reject) => {
  const id = nextId++;
  waiting.set(id, { resolve: done, reject });
  toBrowser.write(JSON.stringify({ id, method, params, sessionId }) + '\0');
});
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

try {
  const { targetId } = await send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await send('Target.attachToTarget', { targetId, flatten: true });
  const page = (method, params) => send(method, params, sessionId);
  await page('Page.enable');
  await page('Emulation.setDeviceMetricsOverride',
             { width: 1300, height: 960, deviceScaleFactor: 1, mobile: false });
  await page('Page.navigate', { url: `file://${site}/index.html?scene=${scene}` });
  const evaluate = async (expression) => (await page('Runtime.evaluate',
    { expression, awaitPromise: true, returnByValue: true })).result.value;
  for (let i = 0; i < 100 && !(await evaluate('Boolean(window.pivotApp)')); ++i) await sleep(100);
  const joint = option('--joint', null);
  if (joint !== null) await evaluate(`window.pivotApp.selectJoint(${Number(joint)})`);
  await sleep(seconds * 1000);
  // The page's clock is coarse (Chromium rounds performance.now() to 0.1 ms on pages that are
  // not cross-origin isolated), so also time a batch of steps in one go, drawing nothing.
  const batch = await evaluate(`(() => { const api = window.pivotApp.api, t = performance.now();
    for (let i = 0; i < 600; ++i) api.step();
    return (performance.now() - t) / 600; })()`);
  console.log(`600 more steps, drawing nothing: ${batch.toFixed(3)} ms a step`);
  const stats = await evaluate(`document.getElementById('stats').textContent + '\\nframes ' +
    window.pivotApp.api.stat(7) + ' steps in ' + (performance.now() / 1000).toFixed(1) +
    ' s of page time'`);
  console.log(`${scene}:\n${stats}`);
  if (screenshot) {
    const { data } = await page('Page.captureScreenshot', { format: 'png' });
    writeFileSync(screenshot, Buffer.from(data, 'base64'));
    console.log(`wrote ${screenshot}`);
  }
} finally {
  browser.kill();
  await sleep(200);
  rmSync(profile, { recursive: true, force: true });
}
