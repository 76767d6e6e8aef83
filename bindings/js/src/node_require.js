// Emscripten 3.1.6's module code loads Node's built-ins with require() and finds its folder by
// __dirname, neither of which an ES module has: this gives it both in Node (top-level await) and
// nothing elsewhere.
const require = typeof process === 'object' && process.versions && process.versions.node
  ? (await import('module')).createRequire(import.meta.url) : undefined;
const __dirname = require
  ? require('path').dirname(require('url').fileURLToPath(import.meta.url)) : undefined;
