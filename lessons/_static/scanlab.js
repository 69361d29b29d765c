/* scanlab lesson figures: the variant switch and the wipe slider. No library, nothing loaded.
 *
 * A figure (<figure class="scanlab-figure">) holds one <div class="scanlab-variant"> per
 * variant (shading, model, scene ...), all but the first hidden, and a row of buttons
 * (.scanlab-switch button[data-variant]) that shows one of them. Inside a variant,
 * .scanlab-wipe lays our image (.scanlab-wipe-over) on VTK's (.scanlab-wipe-base); the
 * range input sets how much of ours is shown, from the left edge.
 */
"use strict";

function scanlabShowVariant(figure, index) {
  for (const v of figure.querySelectorAll(".scanlab-variant")) {
    v.hidden = v.dataset.variant !== String(index);
  }
  for (const b of figure.querySelectorAll(".scanlab-switch button")) {
    b.setAttribute("aria-pressed", String(b.dataset.variant === String(index)));
  }
}

function scanlabSetWipe(wipe, percent) {
  const over = wipe.querySelector(".scanlab-wipe-over");
  over.style.clipPath = "inset(0 " + (100 - percent) + "% 0 0)";
  wipe.style.setProperty("--scanlab-wipe", percent + "%");
}

document.addEventListener("DOMContentLoaded", () => {
  for (const figure of document.querySelectorAll(".scanlab-figure")) {
    for (const b of figure.querySelectorAll(".scanlab-switch button")) {
      b.addEventListener("click", () => scanlabShowVariant(figure, b.dataset.variant));
    }
  }
  for (const wipe of document.querySelectorAll(".scanlab-wipe")) {
    const range = wipe.querySelector("input[type=range]");
    scanlabSetWipe(wipe, Number(range.value));
    range.addEventListener("input", () => scanlabSetWipe(wipe, Number(range.value)));
  }
});
