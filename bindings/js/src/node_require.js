// Emscripten 3.1.6's module code loads Node's built-ins with require(), which an ES module does
// not have: this gives it one in Node (top-level await) and nothing elsewhere.
const require = typeof process === 'object' && process.versions && process.versions.node
  ? (await import('module')).createRequire(import.meta.url) : undefined;
