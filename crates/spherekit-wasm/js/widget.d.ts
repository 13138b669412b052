// Types of widget.js: the <spherekit-view> element and `mount`.
import type { Playground } from './spherekit_wasm.js';

/** Options of {@link mount}. */
export interface MountOptions {
  /** The largest width of the view in CSS pixels (default: the element's width, which the view follows); the canvas has `width × devicePixelRatio` pixels. */
  size?: number;
  /**
   * URL of a spherekit playground page, relative to the document. When given, the view shows a
   * "Playground ↗" link to `<playground>#scene=<the scene>`; without it, no link.
   */
  playground?: string | null;
  /** The smallest plot and legend text in CSS pixels (default 11); 0 draws the figure exactly as the CLI renders it at the view's width. */
  minText?: number;
}

/** What {@link mount} resolves to for a valid scene. */
export interface WidgetHandle {
  /** The wasm handle of the scene (sampling, continuity, camera, drawing). */
  pg: Playground;
  /** Renders the scene again (after changing it through `pg`). */
  redraw(): void;
  /** Stops the animation, empties the element and frees the wasm handle. */
  destroy(): void;
}

/**
 * Shows `scene` (scene JSON text, the format of the spherekit CLI) in `element`: the rendered
 * sphere (drag to turn it), a play button and a slider for t. Loads the wasm module on first use.
 * Resolves to the widget's handle, or to `null` for a bad scene, whose one-line message is shown
 * in place of the view. `element.dataset.state` becomes `"ready"` or `"error"`.
 */
export function mount(element: HTMLElement, scene: string, options?: MountOptions): Promise<WidgetHandle | null>;

declare global {
  /** `<spherekit-view scene="…" size="…" playground="…" min-text="…">`, defined when widget.js is loaded. */
  interface HTMLElementTagNameMap {
    'spherekit-view': HTMLElement;
  }
}
