import { registerNoticeTexts } from '../language/i18n';

/**
 * The boat's loader and the texts of the notices only it raises (why a model could not be had),
 * fetched with the boat after the first frame rather than in the page's first script. A failure
 * to fetch this part itself is said by boatLoadFailed, whose text the page keeps.
 */
export { loadBoatModel } from '../../render/boat/boatModel';

registerNoticeTexts({
  en: {
    boatUnreachable: (v) => `The boat model "${v.url}" could not be fetched. The ocean runs without the boat.`,
    boatNotFound: (v) => `The boat model "${v.url}" was not found (HTTP ${v.status}). The ocean runs without the boat.`,
    boatWebPage: (v) => `The boat model "${v.url}" is missing: the server sent a web page in its place. The ocean runs without the boat.`,
    boatNotGltf: (v) =>
      `The boat model "${v.url}" is not a valid glTF model: neither a binary .glb nor a JSON .gltf file that three.js can read. The ocean runs without the boat.`,
    boatNoGeometry: (v) => `The boat model "${v.url}" has no geometry to float. The ocean runs without the boat.`,
  },
  es: {
    boatUnreachable: (v) => `No se pudo descargar el modelo del barco "${v.url}". El océano sigue sin él.`,
    boatNotFound: (v) => `No se encontró el modelo del barco "${v.url}" (HTTP ${v.status}). El océano sigue sin él.`,
    boatWebPage: (v) => `Falta el modelo del barco "${v.url}": el servidor envió una página web en su lugar. El océano sigue sin él.`,
    boatNotGltf: (v) =>
      `El modelo del barco "${v.url}" no es un glTF válido: ni un .glb binario ni un .gltf JSON que three.js pueda leer. El océano sigue sin él.`,
    boatNoGeometry: (v) => `El modelo del barco "${v.url}" no tiene geometría que pueda flotar. El océano sigue sin él.`,
  },
});
