// The L-system panel: an editor with line numbers and the examples as presets, a derivation
// slider, errors marked at their line → POST /api/lsystem.
const $ = (id) => document.getElementById(id);

export class LsystemPanel {
  constructor(examples) {
    this.presets = new Map(examples.lsystems.map((e) => [e.name, e.text]));
    for (const name of this.presets.keys()) $('ls-preset').append(new Option(name, name));
    $('ls-preset').addEventListener('change', () => this.loadPreset($('ls-preset').value));
    $('ls-text').addEventListener('input', () => this.renderGutter());
    $('ls-text').addEventListener('scroll', () => ($('ls-gutter').scrollTop = $('ls-text').scrollTop));
    $('ls-derivations').addEventListener('input', () => this.showDerivations());
    const first = this.presets.has('tree_3d') ? 'tree_3d' : [...this.presets.keys()][0];
    if (first) {
      $('ls-preset').value = first;
      this.loadPreset(first);
    }
  }

  loadPreset(name) {
    const text = this.presets.get(name) ?? '';
    $('ls-text').value = text;
    const match = /^\s*derivations:\s*(\d+)/m.exec(text);
    if (match) $('ls-derivations').value = match[1];
    this.showDerivations();
    this.markError(undefined);
  }

  showDerivations() {
    $('ls-derivations-value').textContent = $('ls-derivations').value;
  }

  renderGutter() {
    const lines = $('ls-text').value.split('\n').length;
    const gutter = $('ls-gutter');
    gutter.replaceChildren();
    for (let i = 1; i <= lines; ++i) {
      const span = document.createElement('span');
      span.textContent = String(i);
      span.dataset.line = String(i);
      if (i === this.errorLine) span.className = 'error-line';
      gutter.append(span, '\n');
    }
    gutter.scrollTop = $('ls-text').scrollTop;
  }

  /** Marks `line` (1-based) as the error line and puts the cursor there; undefined clears. */
  markError(line, column) {
    this.errorLine = line;
    this.renderGutter();
    if (!line) return;
    const text = $('ls-text').value;
    let offset = 0;
    for (let i = 1; i < line; ++i) offset = text.indexOf('\n', offset) + 1;
    const at = offset + Math.max(0, (column ?? 1) - 1);
    $('ls-text').focus();
    $('ls-text').setSelectionRange(at, at);
  }

  request() {
    const seed = $('ls-seed').value.trim();
    const body = { text: $('ls-text').value, derivations: Number($('ls-derivations').value) };
    if (seed !== '') body.seed = Number(seed);
    if ($('ls-weld').checked || $('ls-union').checked) {
      body.mesh = { weld: true, union: $('ls-union').checked };
      if ($('ls-convex').checked) body.mesh.convex_junctions = true;
    }
    return body;
  }
}
