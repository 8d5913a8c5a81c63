// The colonization panel: a config (envelopes, obstacles, …) with the main growth parameters as
// fields, attraction points shown in the view → POST /api/colonize.
const $ = (id) => document.getElementById(id);

const kFields = [
  ['co-influence', 'influence_radius', 100],
  ['co-kill', 'kill_radius', 20],
  ['co-step', 'step', 15],
  ['co-iterations', 'max_iterations', 1000],
  ['co-seed', 'seed', 0],
];

export class ColonizePanel {
  constructor(examples) {
    this.presets = new Map(examples.colonize.map((e) => [e.name, e.config]));
    for (const name of this.presets.keys()) $('co-preset').append(new Option(name, name));
    $('co-preset').addEventListener('change', () => this.loadPreset($('co-preset').value));
    const first = this.presets.has('broadleaf') ? 'broadleaf' : [...this.presets.keys()][0];
    if (first) {
      $('co-preset').value = first;
      this.loadPreset(first);
    }
  }

  loadPreset(name) {
    const config = structuredClone(this.presets.get(name) ?? {});
    for (const [id, key, fallback] of kFields) {
      $(id).value = config[key] ?? fallback;
      delete config[key];
    }
    $('co-config').value = JSON.stringify(config, null, 2);
  }

  /** The request body; throws a SyntaxError naming the problem when the config is not JSON. */
  request() {
    let config;
    try {
      config = JSON.parse($('co-config').value);
    } catch (e) {
      throw new SyntaxError(`config: ${e.message}`);
    }
    for (const [id, key] of kFields) {
      const text = $(id).value.trim();
      if (text !== '') config[key] = Number(text);
    }
    return { config };
  }

  showPoints() {
    return $('co-show-points').checked;
  }
}
