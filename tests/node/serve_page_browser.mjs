// urdfsnap serve's page in a real browser (Debian's chromium, driven by playwright-core): a model
// broken at start-up shows its error until the good one is written, then the frame appears, a
// dragged slider, an orbit drag, the wheel, a toggle, fit and the focus list change the picture,
// the model broken and fixed on disk shows in the page, and no console error is logged. Writes what
// the shell test checks next with urdfsnap itself: the suite case and pose the page copies, the
// frame it shows, and a screenshot.
// usage: node serve_page_browser.mjs URL MODEL_FILE GOOD_MODEL_FILE OUT_DIR
import { makeChecker, openBrowserPage } from './browser_check.mjs';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';

const [url, modelFile, goodFile, out] = process.argv.slice(2);
const {check, failures} = makeChecker();
const {browser, page, errors} = await openBrowserPage({width: 1180, height: 640});

// the frame the page shows, as bytes (base64), once it has settled (no change for 400 ms)
async function settledFrame() {
  let last = null, same = 0;
  for (let i = 0; i < 200 && same < 8; ++i) {
    await page.waitForTimeout(50);
    const src = await page.$eval('#frame', (img) => (img.complete && img.naturalWidth > 0 ? img.src : ''));
    same = src && src === last ? same + 1 : 0;
    last = src;
  }
  return page.evaluate(async () => {
    const bytes = new Uint8Array(await (await fetch(document.getElementById('frame').src)).arrayBuffer());
    let text = '';
    for (const b of bytes) text += String.fromCharCode(b);
    return btoa(text);
  });
}
const status = () => page.textContent('#status');

// broken at start-up: the page shows the error and waits; the good model written, it starts
await page.goto(url);
await page.waitForSelector('#error:not([hidden])', {timeout: 15000}).catch(() => {});
const atStart = await page.textContent('#error');
check(/urdfsnap: error: .*mrm\.urdf:\d+: link 'base_link' is defined twice/.test(atStart), `a model broken at start-up shows its error (${atStart.trim()})`);
writeFileSync(modelFile, readFileSync(goodFile, 'utf8'));
await page.waitForSelector('#error[hidden]', {state: 'attached', timeout: 15000}).catch(() => {});
check(await page.$eval('#error', (e) => e.hidden), 'the mended model clears the error');
const first = await settledFrame();
check(first.length > 1000, 'the first frame is shown');
check((await page.textContent('#robot-name')) === 'mrm', 'the robot\'s name is the title');
check((await page.locator('#sliders .joint').count()) === 5, 'one slider per movable joint');

// drag a slider as a user would: the number field follows and the picture changes
const slider = page.locator('input[type=range][data-joint="link_01__link_02"]');
const box = await slider.boundingBox();
await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
await page.mouse.down();
for (let step = 1; step <= 20; ++step) await page.mouse.move(box.x + box.width * (0.5 + step * 0.0125), box.y + box.height / 2);
await page.mouse.up();
const moved = await settledFrame();
const value = Number(await page.inputValue('input[type=number][data-joint="link_01__link_02"]'));
check(value > 0.5 && value < 2.2, `the slider moved the joint (${value} rad)`);
check(moved !== first, 'the picture changed with the slider');

// orbit: drag on the picture (yaw, pitch), then the wheel (distance), then a toggle
const view = await page.locator('#frame').boundingBox();
const yawBefore = await status();
await page.mouse.move(view.x + view.width / 2, view.y + view.height / 2);
await page.mouse.down();
await page.mouse.move(view.x + view.width / 2 + 120, view.y + view.height / 2 + 30, {steps: 6});
await page.mouse.up();
const orbited = await settledFrame();
check(orbited !== moved && (await status()) !== yawBefore, `dragging orbits the camera (${await status()})`);
await page.mouse.wheel(0, -300);
const zoomed = await settledFrame();
check(zoomed !== orbited && /distance 6\.4/.test(await status()), `the wheel zooms in as RViz does (${await status()})`);
await page.uncheck('#grid');
const gridless = await settledFrame();
check(gridless !== zoomed, 'the grid toggle changes the picture');

// what the page copies, for the shell test to check with urdfsnap
await page.click('#copy-case');
writeFileSync(join(out, 'case.yaml'), await page.inputValue('#copy-text'));
await page.click('#copy-close');
await page.click('#copy-pose');
writeFileSync(join(out, 'pose.yaml'), await page.inputValue('#copy-text'));
await page.click('#copy-close');
writeFileSync(join(out, 'frame.png'), Buffer.from(gridless, 'base64'));
await page.check('#grid');
const gridded = await settledFrame();
await page.screenshot({path: join(out, 'page.png')});

// fit frames the robot from where the camera looks now; the focus list frames one link
const distanceOf = (text) => Number(/distance ([\d.]+)/.exec(text)[1]);
const zoomedIn = await status();
await page.click('#fit-view');
const fitted = await settledFrame();
const fittedStatus = await status();
check(fitted !== gridded && distanceOf(fittedStatus) !== distanceOf(zoomedIn) && !/focal 0,0,0 /.test(fittedStatus),
      `fit frames the robot, looking at its middle (${fittedStatus})`);
await page.selectOption('#focus', 'link_05');
const focused = await settledFrame();
check(focused !== fitted && distanceOf(await status()) < distanceOf(fittedStatus), `the focus list frames one link (${await status()})`);

// break the model on disk: the page shows the located error by itself; fix it: it recovers
const good = readFileSync(modelFile, 'utf8');
writeFileSync(modelFile, good.replace('</robot>', '<link name="base_link"/></robot>'));
await page.waitForSelector('#error:not([hidden])', {timeout: 15000}).catch(() => {});
const shown = await page.textContent('#error');
check(/urdfsnap: error: .*mrm\.urdf:\d+: link 'base_link' is defined twice/.test(shown), `a broken edit shows its located error (${shown.trim()})`);
writeFileSync(modelFile, good);
await page.waitForSelector('#error[hidden]', {state: 'attached', timeout: 15000}).catch(() => {});
check(await page.$eval('#error', (e) => e.hidden), 'the fixed model clears the error');

check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
await browser.close();
process.exit(failures().length ? 1 : 0);
