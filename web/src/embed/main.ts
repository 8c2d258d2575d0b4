/**
 * The embed page (`embed.html?<share query>&autorotate=1&bg=transparent`): the tree of a share
 * link with orbit controls and an "Open in Sylva" link; errors are shown in the frame.
 */
import { createModuleWorker } from '../createWorker';
import { decodeEdits, decodeQuery, decodeVolumes, EDITS_KEY, VOLUMES_KEY } from 'sylva-trees/url';
import { fatalQueryProblem, openInSylvaUrl, parseEmbedOptions } from './options';
import { TreeEmbed, type EmbedState } from './TreeEmbed';
import { cameraOf, lookFrom } from '../viewer/cameraView';
import '../fonts.css';
import './status.css';
import './embed.css';

/** What tests and the console can read of the embed page. */
declare global {
  interface Window {
    __sylvaEmbed?: {
      state(): EmbedState;
      rotating(): boolean;
      azimuth(): number;
      /** Camera at `from` looking at `to` (m), and where it is now (the gallery's close-ups). */
      view(from: [number, number, number], to: [number, number, number]): void;
      camera(): { position: number[]; target: number[] };
    };
  }
}

function start(): void {
  const view = document.getElementById('embed-view');
  const link = document.getElementById('open-in-sylva');
  if (!view || !(link instanceof HTMLAnchorElement)) throw new Error('embed.html is incomplete');
  const search = window.location.search;
  const options = parseEmbedOptions(search);
  document.documentElement.dataset.bg = options.background.kind;
  link.href = openInSylvaUrl(window.location.href, search);

  const embed = new TreeEmbed(view, {
    workerFactory: createModuleWorker,
    background: options.background,
    autorotate: options.autorotate,
    wind: options.wind,
    onState: (state) => {
      document.body.dataset.status = state.status;
      if (state.status === 'ready') document.body.dataset.hash = state.hash;
    },
  });
  embed.show(({ registry }) => {
    const fatal = fatalQueryProblem(search);
    const decoded = decodeQuery(registry, search);
    const volumes = decodeVolumes(new URLSearchParams(search).get(VOLUMES_KEY));
    // The hand edits of the link (`e=`), as the studio reads them.
    const edits = decodeEdits(new URLSearchParams(search).get(EDITS_KEY));
    // A fatal problem says it all (the codec would add "loaded the defaults").
    const messages = fatal
      ? options.messages
      : [...options.messages, ...decoded.messages, ...volumes.messages, ...edits.messages];
    return {
      params: decoded.params,
      volumes: volumes.volumes,
      edits: edits.edits,
      messages,
      fatal,
    };
  });
  window.__sylvaEmbed = {
    state: () => embed.current,
    rotating: () => embed.rotating,
    azimuth: () => embed.viewer.overlayHost().orbit.getAzimuthalAngle(),
    view: (from, to) => lookFrom(embed.viewer.overlayHost(), from, to),
    camera: () => cameraOf(embed.viewer.overlayHost()),
  };
  window.addEventListener('pagehide', (event) => {
    if (!event.persisted) embed.dispose();
  });
}

start();
