// The skeleton panel: every input of the thesis GUI (seed 000 fig. 6.1) → POST /api/skeleton.
const $ = (id) => document.getElementById(id);

/** A number field's value, or undefined when empty (an empty field has no influence). */
function optionalNumber(id) {
  const text = $(id).value.trim();
  return text === '' ? undefined : Number(text);
}

export class SkeletonPanel {
  constructor(examples) {
    this.saved = undefined;
    for (const s of examples.species) $('sk-example').append(new Option(`${s.name} (${s.class})`, s.name));
    for (const h of examples.head_kinds) $('sk-head').append(new Option(h, h));
    for (const r of examples.resolutions) $('sk-resolution').append(new Option(r, r));
    $('sk-load').addEventListener('change', () => this.load($('sk-load').files[0]));
  }

  async load(file) {
    this.saved = undefined;
    $('sk-loaded').textContent = '';
    if (!file) return;
    try {
      this.saved = JSON.parse(await file.text());
      // The bone list is informative (the design regenerates it): no need to send it.
      delete this.saved.skeleton;
      $('sk-loaded').textContent = `loaded “${this.saved.name ?? file.name}”`;
    } catch (e) {
      $('sk-loaded').textContent = `${file.name}: not JSON (${e.message})`;
    }
  }

  /** The request body. */
  request() {
    const body = {
      legs: optionalNumber('sk-legs'),
      wings: optionalNumber('sk-wings'),
      arms: optionalNumber('sk-arms'),
      fins: optionalNumber('sk-fins'),
      neck_y: optionalNumber('sk-neck-y'),
      tail_x: optionalNumber('sk-tail-x'),
      two_per_girdle: $('sk-two-per-girdle').checked,
      neck_shoulder: $('sk-neck-shoulder').value,
      head: $('sk-head').value,
      example: $('sk-example').value || undefined,
      variations: $('sk-variations').checked,
      count: optionalNumber('sk-count') ?? 1,
      name: $('sk-name').value.trim() || 'skeleton',
      resolution: $('sk-resolution').value,
      seed: optionalNumber('sk-seed'),
      saved: this.saved,
    };
    return JSON.parse(JSON.stringify(body));  // drops undefined fields
  }
}
