import type { Language } from '../language/i18n';

/**
 * The words the lesson cards use, each with the forms it takes in the cards' text (plurals
 * included, in both languages) and a one-sentence definition. The cards link the first
 * occurrence of each term to its definition; the drawer lists them all as the glossary.
 * Spanish keeps the seed report's words: malla, mapa de alturas, oleaje, cabeceo, balanceo.
 */
export interface GlossaryTerm {
  /** The forms the term takes in the cards' text; the first is its headword. */
  words: Record<Language, string[]>;
  definition: Record<Language, string>;
  /** Phrases in which a form means something else ('roll off' is no boat's roll): never linked there. */
  otherSenses?: Partial<Record<Language, string[]>>;
}

export const GLOSSARY = {
  vertex: {
    words: { en: ['vertex', 'vertices'], es: ['vértice', 'vértices'] },
    definition: {
      en: 'A corner point of the mesh’s triangles, with a position and whatever else the shaders need (a normal, texture coordinates).',
      es: 'Un punto esquina de los triángulos de la malla, con una posición y lo que necesiten los shaders (una normal, coordenadas de textura).',
    },
  },
  mesh: {
    words: { en: ['grid', 'grids', 'mesh'], es: ['malla', 'mallas'] },
    definition: {
      en: 'The net of vertices joined into triangles that the GPU draws; the sea’s is a regular grid, denser near the camera.',
      es: 'La red de vértices unidos en triángulos que dibuja la GPU; la del mar es una malla regular, más densa cerca de la cámara.',
    },
  },
  wireframe: {
    words: { en: ['wireframe'], es: ['alambre'] },
    definition: {
      en: 'A way of drawing a mesh with only its triangles’ edges as lines, so its vertices and their density show.',
      es: 'Una forma de dibujar una malla solo con las aristas de sus triángulos como líneas, para que se vean sus vértices y su densidad.',
    },
  },
  vertexShader: {
    words: { en: ['vertex shader'], es: ['vertex shader'] },
    definition: {
      en: 'The GPU program run once per vertex; here it moves each grid point to its place on the waves.',
      es: 'El programa de la GPU que se ejecuta una vez por vértice; aquí lleva cada punto de la malla a su sitio sobre las olas.',
    },
  },
  fragmentShader: {
    words: { en: ['fragment shader'], es: ['fragment shader'] },
    definition: {
      en: 'The GPU program run once per pixel a triangle covers; it computes that pixel’s colour (reflection, refraction, sun, foam).',
      es: 'El programa de la GPU que se ejecuta una vez por cada píxel que cubre un triángulo; calcula su color (reflejo, refracción, sol, espuma).',
    },
  },
  vertexTextureFetch: {
    words: { en: ['vertex texture fetch'], es: ['vertex texture fetch'] },
    definition: {
      en: 'Reading a texture from the vertex shader, so a heightmap stored on the GPU can move the vertices.',
      es: 'Leer una textura desde el vertex shader, para que un mapa de alturas guardado en la GPU pueda mover los vértices.',
    },
  },
  heightmap: {
    words: { en: ['heightmap', 'heightmaps'], es: ['mapa de alturas', 'mapas de alturas'] },
    definition: {
      en: 'An image whose every texel stores a height, read to lift the points of a surface.',
      es: 'Una imagen en la que cada texel guarda una altura, que se lee para elevar los puntos de una superficie.',
    },
  },
  texel: {
    words: { en: ['texel', 'texels'], es: ['texel', 'texels'] },
    definition: {
      en: 'One element of a texture, as a pixel is one element of the screen.',
      es: 'Un elemento de una textura, como un píxel es un elemento de la pantalla.',
    },
  },
  cubeMap: {
    words: { en: ['cube map', 'cube maps'], es: ['cube map', 'cube maps'] },
    definition: {
      en: 'Six square textures on the faces of a cube, looked up by a direction; used here for the sky.',
      es: 'Seis texturas cuadradas en las caras de un cubo, consultadas con una dirección; aquí se usan para el cielo.',
    },
  },
  levelOfDetail: {
    words: { en: ['level of detail'], es: ['nivel de detalle'] },
    definition: {
      en: 'Drawing far parts of a scene with fewer vertices than near ones, so each triangle covers about the same area on screen.',
      es: 'Dibujar las partes lejanas de una escena con menos vértices que las cercanas, para que cada triángulo ocupe en pantalla un área parecida.',
    },
  },
  frustum: {
    words: { en: ['frustum', 'view frustum'], es: ['frustum'] },
    definition: {
      en: 'The truncated pyramid the camera sees, between its near and far planes; what lies wholly outside it need not be drawn.',
      es: 'La pirámide truncada que ve la cámara, entre sus planos cercano y lejano; lo que queda entero fuera de ella no hace falta dibujarlo.',
    },
  },
  normal: {
    words: { en: ['normal', 'normals'], es: ['normal', 'normales'] },
    definition: {
      en: 'The unit vector perpendicular to a surface at a point; lighting and reflection are computed from it.',
      es: 'El vector unitario perpendicular a una superficie en un punto; la iluminación y el reflejo se calculan a partir de él.',
    },
  },
  normalIncidence: {
    words: { en: ['normal incidence'], es: ['incidencia normal'] },
    definition: {
      en: 'Light arriving along the surface’s normal, at 0° from it: looking straight down at a flat sea.',
      es: 'Luz que llega en la dirección de la normal de la superficie, a 0° de ella: mirar en vertical un mar plano.',
    },
  },
  tangentPlane: {
    words: { en: ['tangent plane'], es: ['plano tangente'] },
    definition: {
      en: 'The plane that touches a smooth surface at a point and contains every direction along it there; the normal is perpendicular to it.',
      es: 'El plano que toca una superficie suave en un punto y contiene todas las direcciones a lo largo de ella allí; la normal es perpendicular a él.',
    },
  },
  crossProduct: {
    words: { en: ['cross product'], es: ['producto vectorial'] },
    definition: {
      en: 'The vector a × b perpendicular to both a and b, of length |a||b| sin θ; its sign follows the order of the factors.',
      es: 'El vector a × b perpendicular a a y a b, de longitud |a||b| sen θ; su sentido depende del orden de los factores.',
    },
  },
  lattice: {
    words: { en: ['lattice'], es: ['red'] },
    otherSenses: { es: ['red brillante'] },
    definition: {
      en: 'The regular grid of integer points at which a noise function is given its values, before they are interpolated between.',
      es: 'La rejilla regular de puntos enteros en los que una función de ruido recibe sus valores, antes de interpolar entre ellos.',
    },
  },
  octave: {
    words: { en: ['octave', 'octaves'], es: ['octava', 'octavas'] },
    definition: {
      en: 'One layer of a summed noise, each at twice the frequency of the one before.',
      es: 'Una capa de un ruido sumado, cada una con el doble de frecuencia que la anterior.',
    },
  },
  persistence: {
    words: { en: ['persistence'], es: ['persistencia'] },
    definition: {
      en: 'The factor by which each octave’s amplitude is multiplied relative to the previous one; below 1, fine detail stays faint.',
      es: 'El factor por el que se multiplica la amplitud de cada octava respecto de la anterior; por debajo de 1, el detalle fino queda tenue.',
    },
  },
  amplitude: {
    words: { en: ['amplitude', 'amplitudes'], es: ['amplitud', 'amplitudes'] },
    definition: {
      en: 'The largest departure of a wave from its rest level: half its height from trough to crest.',
      es: 'La mayor separación de una ola respecto de su nivel de reposo: la mitad de su altura de seno a cresta.',
    },
  },
  wavelength: {
    words: { en: ['wavelength', 'wavelengths'], es: ['longitud de onda', 'longitudes de onda'] },
    definition: {
      en: 'The distance between two successive crests, λ = 2π/k for a wavenumber k.',
      es: 'La distancia entre dos crestas sucesivas, λ = 2π/k para un número de onda k.',
    },
  },
  crest: {
    words: { en: ['crest', 'crests'], es: ['cresta', 'crestas'] },
    definition: {
      en: 'The highest point of a wave, half a wavelength from the lowest, its trough.',
      es: 'El punto más alto de una ola, a media longitud de onda del más bajo, su seno.',
    },
  },
  trochoid: {
    words: { en: ['trochoid', 'trochoids'], es: ['trocoide', 'trocoides'] },
    definition: {
      en: 'The curve traced by a point inside a rolling circle: the profile of a Gerstner wave, sharper at the crests than a sine.',
      es: 'La curva que traza un punto interior de un círculo que rueda: el perfil de una ola de Gerstner, más afilado en las crestas que un seno.',
    },
  },
  swell: {
    words: { en: ['swell'], es: ['oleaje'] },
    definition: {
      en: 'Long, regular waves that have left the wind that raised them and travel on far from it.',
      es: 'Olas largas y regulares que han dejado atrás el viento que las levantó y viajan lejos de él.',
    },
  },
  phaseSpeed: {
    words: { en: ['phase speed'], es: ['velocidad de fase'] },
    definition: {
      en: 'The speed c = ω/k at which a wave’s crests travel.',
      es: 'La velocidad c = ω/k a la que avanzan las crestas de una ola.',
    },
  },
  dispersion: {
    words: { en: ['dispersion', 'dispersive'], es: ['dispersión', 'dispersiva'] },
    definition: {
      en: 'The dependence of a wave’s frequency on its wavenumber, ω(k); in deep water ω² = g k, so longer waves travel faster.',
      es: 'La dependencia de la frecuencia de una ola respecto de su número de onda, ω(k); en aguas profundas ω² = g k, así que las olas largas viajan más rápido.',
    },
  },
  spectrum: {
    words: { en: ['spectrum', 'spectra'], es: ['espectro', 'espectros'] },
    definition: {
      en: 'How a sea’s energy is shared among its frequencies (and directions), S(ω): the recipe a random sea is drawn from.',
      es: 'Cómo se reparte la energía de un mar entre sus frecuencias (y direcciones), S(ω): la receta de la que se extrae un mar aleatorio.',
    },
  },
  significantHeight: {
    words: { en: ['significant wave height', 'significant height'], es: ['altura significativa'] },
    definition: {
      en: 'Hs, four times the standard deviation of the surface’s height: close to the mean height of the highest third of the waves.',
      es: 'Hs, cuatro veces la desviación típica de la altura de la superficie: cercana a la altura media del tercio de olas más altas.',
    },
  },
  fetch: {
    words: { en: ['fetch'], es: ['fetch'] },
    definition: {
      en: 'The distance of open water over which the wind has blown on the sea; a short fetch keeps the waves young and short.',
      es: 'La distancia de mar abierto sobre la que ha soplado el viento; un fetch corto mantiene las olas jóvenes y cortas.',
    },
  },
  fft: {
    words: { en: ['FFT'], es: ['FFT'] },
    definition: {
      en: 'The fast Fourier transform: computes the N-point discrete Fourier transform in O(N log N) steps instead of O(N²), here turning a spectrum into a grid of heights.',
      es: 'La transformada rápida de Fourier: calcula la transformada discreta de Fourier de N puntos en O(N log N) pasos en vez de O(N²); aquí convierte un espectro en una malla de alturas.',
    },
  },
  jacobian: {
    words: { en: ['Jacobian'], es: ['jacobiano'] },
    definition: {
      en: 'The determinant of the derivatives of a map; where the sea’s horizontal displacement makes it negative, the surface folds over itself.',
      es: 'El determinante de las derivadas de una transformación; donde el desplazamiento horizontal del mar lo vuelve negativo, la superficie se pliega sobre sí misma.',
    },
  },
  foam: {
    words: { en: ['foam'], es: ['espuma'] },
    definition: {
      en: 'Air bubbles mixed into the water where waves break; it whitens the surface and fades over seconds.',
      es: 'Burbujas de aire mezcladas con el agua donde rompen las olas; blanquea la superficie y se desvanece en segundos.',
    },
  },
  wake: {
    words: { en: ['wake', 'wakes'], es: ['estela', 'estelas'] },
    definition: {
      en: 'The waves a moving boat leaves behind it.',
      es: 'Las olas que un barco en movimiento deja tras de sí.',
    },
  },
  kelvinWake: {
    words: { en: ['Kelvin wake'], es: ['estela de Kelvin', 'estela analítica de Kelvin'] },
    definition: {
      en: 'The wake of a body moving steadily over deep water, confined to a wedge of half-angle arcsin(1/3) ≈ 19.47° whatever its speed.',
      es: 'La estela de un cuerpo que avanza a velocidad constante en aguas profundas, limitada a una cuña de semiángulo arcsen(1/3) ≈ 19,47° sea cual sea su velocidad.',
    },
  },
  heave: {
    words: { en: ['heave'], es: ['elevación'] },
    definition: {
      en: 'A boat’s up-and-down motion as a whole.',
      es: 'El movimiento de subida y bajada del barco entero.',
    },
  },
  pitch: {
    words: { en: ['pitch'], es: ['cabeceo'] },
    definition: {
      en: 'A boat’s rotation about its side-to-side axis: the bow rising and the stern falling, and back.',
      es: 'El giro del barco en torno a su eje transversal: la proa sube y la popa baja, y al revés.',
    },
  },
  roll: {
    words: { en: ['roll'], es: ['balanceo'] },
    otherSenses: { en: ['roll off'] },
    definition: {
      en: 'A boat’s rotation about its bow-to-stern axis, from one side to the other.',
      es: 'El giro del barco en torno a su eje de proa a popa, de un costado al otro.',
    },
  },
  reflectance: {
    words: { en: ['reflectance'], es: ['reflectancia'] },
    definition: {
      en: 'The fraction of the light arriving at a surface that it reflects.',
      es: 'La fracción de la luz que llega a una superficie que esta refleja.',
    },
  },
  fresnelEquations: {
    words: { en: ['Fresnel equations'], es: ['ecuaciones de Fresnel'] },
    definition: {
      en: 'The equations giving how much light a boundary between two media reflects, for each polarisation, from the angle and the refractive indices.',
      es: 'Las ecuaciones que dan cuánta luz refleja la frontera entre dos medios, para cada polarización, a partir del ángulo y de los índices de refracción.',
    },
  },
  schlick: {
    words: { en: ['Schlick’s approximation'], es: ['aproximación de Schlick'] },
    definition: {
      en: 'F ≈ R₀ + (1 − R₀)(1 − cos θ)⁵: a cheap fit to the Fresnel reflectance that is exact at 0° and at 90°.',
      es: 'F ≈ R₀ + (1 − R₀)(1 − cos θ)⁵: un ajuste barato de la reflectancia de Fresnel, exacto a 0° y a 90°.',
    },
  },
  snellsLaw: {
    words: { en: ['Snell’s law'], es: ['ley de Snell'] },
    definition: {
      en: 'n₁ sin θ₁ = n₂ sin θ₂: how a ray bends as it crosses from one medium into another.',
      es: 'n₁ sen θ₁ = n₂ sen θ₂: cómo se desvía un rayo al pasar de un medio a otro.',
    },
  },
  criticalAngle: {
    words: { en: ['critical angle'], es: ['ángulo crítico'] },
    definition: {
      en: 'The angle of incidence, arcsin(n₂/n₁), beyond which light in the denser medium cannot leave it and is totally reflected.',
      es: 'El ángulo de incidencia, arcsen(n₂/n₁), a partir del cual la luz en el medio más denso no puede salir de él y se refleja totalmente.',
    },
  },
  snellsWindow: {
    words: { en: ['Snell’s window'], es: ['ventana de Snell'] },
    definition: {
      en: 'The circle overhead through which someone under water sees the whole sky, its edge at the critical angle, 48.6° from the vertical.',
      es: 'El círculo sobre la cabeza por el que quien está bajo el agua ve todo el cielo, con su borde en el ángulo crítico, a 48,6° de la vertical.',
    },
  },
  meanSquareSlope: {
    words: { en: ['mean-square slope'], es: ['pendiente cuadrática media'] },
    definition: {
      en: 'σ², the mean of the squared slopes of a surface’s facets: how rough it is, and how wide the sun’s glitter spreads.',
      es: 'σ², la media de los cuadrados de las pendientes de las facetas de una superficie: cuán rugosa es y cuánto se extiende el destello del sol.',
    },
  },
  beckmann: {
    words: { en: ['Beckmann distribution'], es: ['distribución de Beckmann'] },
    definition: {
      en: 'A Gaussian distribution of microfacet slopes, set by one mean-square slope, used to spread a highlight over a rough surface.',
      es: 'Una distribución gaussiana de las pendientes de las microfacetas, fijada por una pendiente cuadrática media, con la que se reparte un brillo sobre una superficie rugosa.',
    },
  },
  toneCurve: {
    words: { en: ['tone curve'], es: ['curva de tono'] },
    definition: {
      en: 'The function that maps the scene’s light, which can be far brighter than white, to the screen’s range from black to white.',
      es: 'La función que lleva la luz de la escena, que puede ser mucho más brillante que el blanco, al rango de la pantalla, de negro a blanco.',
    },
  },
  exposure: {
    words: { en: ['exposure'], es: ['exposición'] },
    definition: {
      en: 'The factor that scales all the scene’s light before the tone curve, as a camera’s shutter and aperture do.',
      es: 'El factor que escala toda la luz de la escena antes de la curva de tono, como el obturador y el diafragma de una cámara.',
    },
  },
  beerLambert: {
    words: { en: ['Beer–Lambert law'], es: ['ley de Beer–Lambert'] },
    definition: {
      en: 'Light crossing an absorbing medium keeps the fraction e^(−c d) after a distance d, for an attenuation coefficient c.',
      es: 'La luz que atraviesa un medio absorbente conserva la fracción e^(−c d) tras una distancia d, para un coeficiente de atenuación c.',
    },
  },
  caustics: {
    words: { en: ['caustics'], es: ['cáusticas'] },
    definition: {
      en: 'The bright pattern where light bent by a curved surface converges, as on a sea bed under waves.',
      es: 'El dibujo brillante donde converge la luz desviada por una superficie curva, como en el fondo bajo las olas.',
    },
  },
  godRays: {
    words: { en: ['god rays'], es: ['rayos de luz'] },
    definition: {
      en: 'Shafts of sunlight made visible by the particles and water that scatter part of it towards the eye.',
      es: 'Haces de luz solar que se hacen visibles porque las partículas y el agua dispersan parte de ella hacia el ojo.',
    },
  },
  gaussianBlur: {
    words: { en: ['Gaussian blur'], es: ['desenfoque gaussiano'] },
    definition: {
      en: 'A blur that replaces each pixel by an average of its neighbours weighted by a Gaussian of their distance.',
      es: 'Un desenfoque que sustituye cada píxel por una media de sus vecinos ponderada por una gaussiana de su distancia.',
    },
  },
  groupVelocity: {
    words: { en: ['group velocity'], es: ['velocidad de grupo'] },
    definition: {
      en: 'The speed c_g = dω/dk at which a group of waves, and the energy it carries, travels: c/2 in deep water, c in shallow water.',
      es: 'La velocidad c_g = dω/dk a la que viaja un grupo de olas, y la energía que lleva: c/2 en aguas profundas, c en aguas someras.',
    },
  },
  refraction: {
    words: { en: ['refraction'], es: ['refracción'] },
    definition: {
      en: 'The turning of a wave where its speed changes across its front: light entering water, or sea waves turning towards shallower water.',
      es: 'El giro de una onda donde su velocidad cambia a lo largo de su frente: la luz que entra en el agua, o las olas que giran hacia el agua más somera.',
    },
  },
  depthContour: {
    words: { en: ['depth contours', 'depth contour'], es: ['isóbatas', 'isóbata'] },
    definition: {
      en: 'A line on the sea floor joining points of equal depth; on the beach they run straight along the shore, round the island they are circles.',
      es: 'Una línea del fondo que une puntos de igual profundidad; en la playa corren rectas a lo largo de la costa, alrededor de la isla son círculos.',
    },
  },
  shoaling: {
    words: { en: ['shoaling'], es: ['asomeramiento'] },
    definition: {
      en: 'The change of a wave’s height as it runs into shallower water and its group velocity changes, its energy flux kept: H/H₀ = √(c_g0/c_g).',
      es: 'El cambio de altura de una ola al entrar en agua más somera y cambiar su velocidad de grupo, conservando su flujo de energía: H/H₀ = √(c_g0/c_g).',
    },
  },
  breakerIndex: {
    words: { en: ['breaker index'], es: ['índice de rotura'] },
    definition: {
      en: 'The ratio γ = H/h of a breaking wave’s height to the depth; McCowan’s solitary wave gives 0.78, real beaches 0.5 to 1.',
      es: 'El cociente γ = H/h entre la altura de una ola que rompe y la profundidad; la onda solitaria de McCowan da 0,78, las playas reales de 0,5 a 1.',
    },
  },
  surfZone: {
    words: { en: ['surf zone'], es: ['zona de rompientes'] },
    definition: {
      en: 'The strip between the breaking line and the shore where the waves are breaking, their height limited by the depth and their crests white with foam.',
      es: 'La franja entre la línea de rotura y la orilla donde las olas rompen, con su altura limitada por la profundidad y sus crestas blancas de espuma.',
    },
  },
} satisfies Record<string, GlossaryTerm>;

export type GlossaryKey = keyof typeof GLOSSARY;
