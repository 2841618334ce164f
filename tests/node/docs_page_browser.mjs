// Pages of `urdfsnap docs` in a real browser (Debian's chromium, driven by playwright-core), opened
// from disk as a reader would: every image loads and decodes with a non-zero size, nothing is
// logged to the console and no request fails, every movable joint named has its section; and every
// link of the page's README.md resolves to a file in the page that the browser decodes.
// usage: node docs_page_browser.mjs PAGE_DIR JOINT,JOINT,... [SCREENSHOT.png]
import { makeChecker, openBrowserPage } from './browser_check.mjs';
import { existsSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const [dir, jointList, screenshot] = process.argv.slice(2);
const joints = jointList ? jointList.split(',') : [];
const {check, failures} = makeChecker();
const {browser, page, errors} = await openBrowserPage({width: 1200, height: 900});
page.on('requestfailed', (request) => errors.push(`request failed: ${request.url()}`));

await page.goto(pathToFileURL(resolve(dir, 'index.html')).href, {waitUntil: 'load'});

// every image decodes (animations included) and has a size
const images = await page.$$eval('img', (all) => Promise.all(all.map(async (img) => {
  let decoded = true;
  try { await img.decode(); } catch { decoded = false; }
  return {src: img.getAttribute('src'), decoded, width: img.naturalWidth, height: img.naturalHeight};
})));
check(images.length > 0, `the page has images (${images.length})`);
const broken = images.filter((i) => !i.decoded || i.width === 0 || i.height === 0).map((i) => i.src);
check(broken.length === 0, `every image decodes with a size${broken.length ? ': not ' + broken.join(', ') : ''}`);

// a section per movable joint, its pictures inside
for (const joint of joints) {
  const section = page.locator(`section.joint[data-joint="${joint.replaceAll('"', '\\"')}"]`);
  const count = await section.count();
  const pictures = count === 1 ? await section.locator('img').count() : 0;
  check(count === 1 && pictures >= 3, `joint '${joint}' has its section with pictures (${count}, ${pictures})`);
}
check((await page.locator('section.joint').count()) === joints.length, 'no other joint sections');
check((await page.locator('#tree li').count()) > 0, 'the tree is a list of links');
check((await page.locator('#joints tr').count()) > 1 && (await page.locator('#links tr').count()) > 1, 'both tables have rows');
if (screenshot) await page.screenshot({path: screenshot, fullPage: true});

// the README's links: files of the page that the browser decodes
const markdown = readFileSync(join(dir, 'README.md'), 'utf8');
const targets = [...markdown.matchAll(/\]\(([^)\s]+)\)/g)].map((m) => m[1]).filter((t) => !t.startsWith('#'));
check(targets.length >= images.length, `the README links to the images (${targets.length})`);
const anchors = [...markdown.matchAll(/\]\(#([^)]+)\)/g)].map((m) => m[1]);
for (const anchor of new Set(anchors)) {
  check(markdown.includes(`<a id="${anchor}"></a>`), `the README's link #${anchor} has its anchor`);
}
const missing = targets.filter((t) => /^[a-z]+:/i.test(t) || !existsSync(join(dir, decodeURIComponent(t))));
check(missing.length === 0, `every README link is a file of the page${missing.length ? ': not ' + missing.join(', ') : ''}`);
const undecodable = await page.evaluate((urls) => Promise.all(urls.map(async (url) => {
  const img = new Image();
  img.src = url;
  try { await img.decode(); return img.naturalWidth > 0 ? null : url; } catch { return url; }
})), targets.filter((t) => !missing.includes(t)));
const bad = undecodable.filter((u) => u);
check(bad.length === 0, `every README link decodes as an image${bad.length ? ': not ' + bad.join(', ') : ''}`);

check(errors.length === 0, `no console errors${errors.length ? ': ' + errors.join(' | ') : ''}`);
await browser.close();
process.exit(failures().length ? 1 : 0);
