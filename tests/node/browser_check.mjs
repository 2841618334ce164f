// What the browser tests share: Debian's chromium launched headless through playwright-core as
// root can run it, a page whose console errors and page errors are collected, and ok/FAIL lines.
import { chromium } from 'playwright-core';

// Launches /usr/bin/chromium headless (playwright starts every launch with a fresh
// --user-data-dir of its own) and opens a page of `viewport`; `errors` collects what the page logs
// as errors and its uncaught exceptions.
export async function openBrowserPage(viewport) {
  const browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const page = await browser.newPage({viewport});
  const errors = [];
  page.on('console', (message) => { if (message.type() === 'error') errors.push(message.text()); });
  page.on('pageerror', (error) => errors.push(error.message));
  return {browser, page, errors};
}

// Prints "ok   WHAT" or "FAIL WHAT"; failures() lists the failed ones.
export function makeChecker() {
  const failed = [];
  const check = (ok, what) => { if (!ok) failed.push(what); console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); };
  return {check, failures: () => failed};
}
