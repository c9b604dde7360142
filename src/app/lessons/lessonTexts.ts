import type { Language } from '../language/i18n';
import type { ReferenceKey } from './bibliography';

/**
 * What each lesson card says: what you see and why, in our own words (40 to 120 words in
 * each language), and its key equations as MathML, which browsers draw without a library.
 * A chunk of its own, fetched with the lessons drawer after the first frame.
 */
export interface LessonText {
  text: Record<Language, string>;
  /** One or more <math> elements. */
  math: string;
  /**
   * Asked before the student touches anything; the answer waits behind a button, and the
   * live view shows it.
   */
  question?: { ask: Record<Language, string>; answer: Record<Language, string> };
  /** One line where the quoted code is a stand-in or an artistic choice, not physics. */
  choice?: Record<Language, string>;
  /** The works behind the card (keys of BIBLIOGRAPHY in bibliography.ts). */
  references?: ReferenceKey[];
}

const m = (body: string) => `<math display="block">${body}</math>`;

export const LESSON_TEXTS: Record<string, LessonText> = {
  'flat-plane': {
    text: {
      en: 'The ocean starts as a flat grid of vertices, drawn here as a wireframe. Near the camera the grid is dense; farther away each chunk keeps fewer vertices, so the triangles stay about the same size on screen. Nothing moves yet: every vertex sits at height zero. The vertex shader receives each grid point (x, z) and is about to ask the wave model where it goes.',
      es: 'El océano empieza como una malla plana de vértices, dibujada aquí en alambre. Cerca de la cámara la malla es densa; más lejos cada parcela conserva menos vértices, así que los triángulos tienen en pantalla un tamaño parecido. Todavía nada se mueve: cada vértice está a altura cero. El vertex shader recibe cada punto (x, z) de la malla y está a punto de preguntar al modelo de olas adónde va.',
    },
    math: m('<mi>P</mi><mo>=</mo><mo>(</mo><mi>x</mi><mo>,</mo><mn>0</mn><mo>,</mo><mi>z</mi><mo>)</mo>'),
  },
  'displaced-plane': {
    text: {
      en: 'The same grid, now displaced. For every vertex the shader evaluates the displacement function M(x, z) and lifts the point by that height: the seed’s “displacement shader”. The CPU sends the flat grid only once; the GPU moves every vertex every frame, so animating the sea costs no upload. The seed’s model only lifts points, so a vertex never moves sideways.',
      es: 'La misma malla, ahora desplazada. Para cada vértice el shader evalúa la función de desplazamiento M(x, z) y eleva el punto esa altura: el “displacement shader” del informe. La CPU envía la malla plana una sola vez; la GPU mueve cada vértice en cada fotograma, así que animar el mar no cuesta ninguna subida de datos. El modelo semilla solo eleva los puntos: ningún vértice se mueve de lado.',
    },
    math: m('<mi>P</mi><mo>=</mo><mo>(</mo><mi>x</mi><mo>,</mo><mi>M</mi><mo>(</mo><mi>x</mi><mo>,</mo><mi>z</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>,</mo><mi>z</mi><mo>)</mo>'),
  },
  swell: {
    text: {
      en: 'The swell is a product of a sine of x and a cosine of z, times an amplitude, with phases that grow with time (the cosine’s at 0.7 of the sine’s rate) so the pattern travels and changes. A second, smaller product turned by 37° breaks the regular egg-box look. The phase speed follows deep-water dispersion, ω = √(g k), so longer swell runs faster, as at sea. The frequency slider sets k, the amplitude slider A.',
      es: 'El oleaje es el producto de un seno de x y un coseno de z, por una amplitud, con fases que crecen con el tiempo (la del coseno a 0,7 del ritmo de la del seno) para que el dibujo avance y cambie. Un segundo producto, menor y girado 37°, rompe el aspecto regular de huevera. La velocidad de fase sigue la dispersión en aguas profundas, ω = √(g k): el oleaje largo corre más, como en el mar. El control de frecuencia fija k; el de amplitud, A.',
    },
    math: m('<mi>h</mi><mo>=</mo><mi>A</mi><mspace width="0.2em"/><mi>sin</mi><mo>(</mo><mi>k</mi><mi>x</mi><mo>+</mo><mi>ω</mi><mi>t</mi><mo>)</mo><mspace width="0.2em"/><mi>cos</mi><mo>(</mo><mi>k</mi><mi>z</mi><mo>+</mo><mn>0.7</mn><mi>ω</mi><mi>t</mi><mo>)</mo>') + m('<mi>ω</mi><mo>=</mo><msqrt><mi>g</mi><mi>k</mi></msqrt>'),
  },
  'swell-maximum': {
    text: {
      en: 'The swell at the top of both ranges: 4 m of amplitude and 0.2 rad/m, a wavelength of about 31 m. The crests are now steep and close together, and the grid starts to show its vertices along them. The shader counts angles in turns and keeps only the fraction, so the argument k x stays small even kilometres from the origin, where float32 would otherwise lose the phase.',
      es: 'El oleaje en lo más alto de ambos rangos: 4 m de amplitud y 0,2 rad/m, una longitud de onda de unos 31 m. Las crestas son ahora empinadas y cercanas, y la malla empieza a mostrar sus vértices en ellas. El shader cuenta los ángulos en vueltas y conserva solo la fracción, así que el argumento k x sigue siendo pequeño incluso a kilómetros del origen, donde float32 perdería la fase.',
    },
    math: m('<mi>λ</mi><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi></mrow><mi>k</mi></mfrac><mo>≈</mo><mn>31</mn><mspace width="0.2em"/><mtext>m</mtext>'),
    question: {
      ask: { en: 'At k = 0.2 rad/m, how far apart will two crests be?', es: 'Con k = 0,2 rad/m, ¿a qué distancia estarán dos crestas?' },
      answer: { en: 'About 31 m: the wavelength is 2π/k = 2π/0.2 ≈ 31.4 m.', es: 'Unos 31 m: la longitud de onda es 2π/k = 2π/0,2 ≈ 31,4 m.' },
    },
    choice: { en: 'The sliders’ ends, 4 m and 0.2 rad/m, are the app’s limits, not the sea’s.', es: 'Los extremos de los controles, 4 m y 0,2 rad/m, son límites de la aplicación, no del mar.' },
    references: ['deanDalrymple1991'],
  },
  'perlin-hash': {
    text: {
      en: 'Perlin noise, as the seed builds it, begins with an integer noise function: the same lattice point and seed always give the same value in [−1, 1), with no pattern between neighbours. The picture is that function on a lattice of 16 × 16 points, one grey square per value (the first heightmap’s third octave). Ours mixes the coordinates with the MurmurHash3 finaliser in exact 32-bit arithmetic, so every browser computes the same heightmaps. On its own this noise is harsh; the next steps smooth it.',
      es: 'El ruido de Perlin, como lo construye el informe, empieza con una función de ruido entera: el mismo punto de la red y la misma semilla dan siempre el mismo valor en [−1, 1), sin patrón entre vecinos. La imagen es esa función en una red de 16 × 16 puntos, un cuadrado gris por valor (la tercera octava del primer mapa de alturas). La nuestra mezcla las coordenadas con el finalizador de MurmurHash3 en aritmética exacta de 32 bits, así que todos los navegadores calculan los mismos mapas de alturas. Solo, este ruido es áspero; los pasos siguientes lo suavizan.',
    },
    math: m('<mi>n</mi><mo>(</mo><mi>i</mi><mo>,</mo><mi>j</mi><mo>)</mo><mo>∈</mo><mo>[</mo><mo>−</mo><mn>1</mn><mo>,</mo><mn>1</mn><mo>)</mo>'),
  },
  'perlin-smoothing': {
    text: {
      en: 'Step two replaces each lattice value by a weighted mean of its 3 × 3 neighbourhood: a quarter for the point itself, an eighth for each side, a sixteenth for each corner. Left, the integer noise of step one; right, the same lattice smoothed. The weights add up to one, so the noise keeps its range but loses its sharpest jumps: the greys draw towards the middle. The lattice wraps at its own period, which is what lets the heightmaps tile the sea without a seam.',
      es: 'El segundo paso sustituye cada valor de la red por una media ponderada de sus 3 × 3 vecinos: un cuarto para el propio punto, un octavo para cada lado y un dieciseisavo para cada esquina. A la izquierda, el ruido entero del paso uno; a la derecha, la misma red suavizada. Los pesos suman uno, así que el ruido conserva su rango pero pierde sus saltos más bruscos: los grises se acercan al centro. La red se repite con su propio periodo, y eso permite que los mapas de alturas cubran el mar sin costuras.',
    },
    math: m('<mi>s</mi><mo>=</mo><mfrac><mi>c</mi><mn>16</mn></mfrac><mo>+</mo><mfrac><mi>e</mi><mn>8</mn></mfrac><mo>+</mo><mfrac><mi>n</mi><mn>4</mn></mfrac>'),
  },
  'perlin-octaves': {
    text: {
      en: 'Step three interpolates between lattice points with a cosine curve, flat at both ends: left, the smoothed lattice of step two, now a smooth surface. Then octaves are added: each has twice the frequency of the previous one and its amplitude multiplied by the persistence, 0.62. Right, five octaves summed: large soft hills with fine detail on top. That is the first heightmap exactly as the vertex shader receives it, made at start-up from the seed.',
      es: 'El tercer paso interpola entre puntos de la red con una curva coseno, plana en ambos extremos: a la izquierda, la red suavizada del paso dos, ahora una superficie suave. Después se suman octavas: cada una con el doble de frecuencia que la anterior y su amplitud multiplicada por la persistencia, 0,62. A la derecha, cinco octavas sumadas: colinas grandes y suaves con detalle fino encima. Es el primer mapa de alturas tal como lo recibe el vertex shader, generado al arrancar a partir de la semilla.',
    },
    math: m('<mi>N</mi><mo>(</mo><mi>u</mi><mo>)</mo><mo>=</mo><mfrac><mrow><munder><mo>∑</mo><mi>o</mi></munder><msup><mi>p</mi><mi>o</mi></msup><mspace width="0.2em"/><msub><mi>n</mi><mi>o</mi></msub><mo>(</mo><msup><mn>2</mn><mi>o</mi></msup><mi>u</mi><mo>)</mo></mrow><mrow><munder><mo>∑</mo><mi>o</mi></munder><msup><mi>p</mi><mi>o</mi></msup></mrow></mfrac>'),
  },
  'heightmap-blend': {
    text: {
      en: 'The vertex shader reads both heightmaps as textures (vertex texture fetch) and mixes them with a weight b that swings slowly with time: left H₀, right H₁, in the middle their mix at this instant, what the ripples are made of now. Each map also drifts across the sea at its own speed. Because one fades in as the other fades out, the pattern keeps changing and never visibly repeats, though each map is only a small tile. Set View to ocean to see the ripples alone.',
      es: 'El vertex shader lee ambos mapas de alturas como texturas (vertex texture fetch) y los mezcla con un peso b que oscila despacio con el tiempo: a la izquierda H₀, a la derecha H₁, en el centro su mezcla en este instante, de la que están hechas ahora las ondas. Además, cada mapa se desliza sobre el mar a su propia velocidad. Como uno aparece mientras el otro se desvanece, el dibujo cambia sin cesar y no se ve que se repita, aunque cada mapa sea solo un pequeño mosaico. Pon Vista en ocean para ver las ondas solas.',
    },
    math: m('<mi>r</mi><mo>=</mo><mi>S</mi><mspace width="0.2em"/><mo>[</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>b</mi><mo>)</mo><msub><mi>H</mi><mn>0</mn></msub><mo>+</mo><mi>b</mi><msub><mi>H</mi><mn>1</mn></msub><mo>]</mo>'),
  },
  'normals-wrong': {
    text: {
      en: 'The seed’s “wrong normals”: the vertices move, but each keeps the flat plane’s normal (0, 1, 0). Colour shows the normal (x, y, z as red, green, blue), so the whole sea is one flat green: the lighting cannot see the waves, only the silhouette moves. Switch Normals to fabricated to see the difference the next lesson explains.',
      es: 'Las “normales incorrectas” del informe: los vértices se mueven, pero cada uno conserva la normal del plano, (0, 1, 0). El color muestra la normal (x, y, z como rojo, verde, azul), así que todo el mar es un mismo verde plano: la iluminación no ve las olas, solo se mueve la silueta. Cambia Normales a fabricadas para ver la diferencia que explica la lección siguiente.',
    },
    math: m('<mi>N</mi><mo>=</mo><mo>(</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>,</mo><mn>0</mn><mo>)</mo>'),
  },
  'normals-right': {
    text: {
      en: 'Right normals, as the seed fabricates them. Besides the vertex V1, the shader evaluates M at two invented neighbours, V2 a small step along x and V3 a step along z. The two edges from V1 span the tangent plane, and their cross product is the normal. Colours now change across every wave: slopes towards x turn red, slopes towards z blue.',
      es: 'Normales correctas, como las fabrica el informe. Además del vértice V1, el shader evalúa M en dos vecinos inventados: V2, un pequeño paso en x, y V3, un paso en z. Las dos aristas desde V1 generan el plano tangente, y su producto vectorial es la normal. Ahora los colores cambian en cada ola: las pendientes hacia x se vuelven rojas, las pendientes hacia z, azules.',
    },
    math: m('<mi>N</mi><mo>=</mo><mo>(</mo><msub><mi>V</mi><mn>3</mn></msub><mo>−</mo><msub><mi>V</mi><mn>1</mn></msub><mo>)</mo><mo>×</mo><mo>(</mo><msub><mi>V</mi><mn>2</mn></msub><mo>−</mo><msub><mi>V</mi><mn>1</mn></msub><mo>)</mo>'),
  },
  'sky-cube': {
    text: {
      en: 'The sky is a cube map: six square images, one per face of a cube around the camera. Here it is unfolded into a cross, seen from inside: the middle row is the horizon all round, from −x through −z (straight ahead) to +x and +z, with the sky, +y, above and −y below. A direction is enough to look it up; the GPU picks the face and the texel. Move the sun and the six faces are painted again; set View to ocean to see this sky behind the sea.',
      es: 'El cielo es un cube map: seis imágenes cuadradas, una por cara de un cubo alrededor de la cámara. Aquí está desplegado en una cruz, visto desde dentro: la fila central es el horizonte entero, de −x pasando por −z (de frente) a +x y +z, con el cielo, +y, arriba y −y abajo. Basta una dirección para consultarlo; la GPU elige la cara y el texel. Al mover el sol se vuelven a pintar las seis caras; pon Vista en ocean para ver este cielo detrás del mar.',
    },
    math: m('<mtext>color</mtext><mo>=</mo><mtext>texCUBE</mtext><mo>(</mo><mi>sky</mi><mo>,</mo><mover><mi>d</mi><mo>^</mo></mover><mo>)</mo>'),
  },
  reflection: {
    text: {
      en: 'A still sea is a mirror: with no swell and no ripples, what you see is the cube map looked up along the reflected view ray. The shader reflects the direction to the eye about the normal, clamps rays that would point below the horizon, and mixes the sky with the water’s own colour by the Fresnel reflectance. Near the horizon the sea reflects nearly everything. Switch the roughness on and the slopes the mesh does not show blur the sky; on this sea they are the same everywhere, so the blurred sky is painted once into a small cube that each pixel reads once.',
      es: 'Un mar en calma es un espejo: sin oleaje ni ondas, lo que se ve es el cube map consultado en la dirección del rayo de vista reflejado. El shader refleja la dirección hacia el ojo respecto de la normal, limita los rayos que apuntarían bajo el horizonte y mezcla el cielo con el color propio del agua según la reflectancia de Fresnel. Cerca del horizonte el mar lo refleja casi todo. Activa la rugosidad y las pendientes que la malla no muestra desenfocan el cielo; en este mar son iguales en todas partes, así que el cielo desenfocado se pinta una vez en un cubo pequeño que cada píxel lee una sola vez.',
    },
    math: m('<mi>r</mi><mo>=</mo><mi>v</mi><mo>−</mo><mn>2</mn><mo>(</mo><mi>v</mi><mo>·</mo><mi>n</mi><mo>)</mo><mi>n</mi>') + m('<mi>c</mi><mo>=</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>F</mi><mo>)</mo><msub><mi>c</mi><mtext>water</mtext></msub><mo>+</mo><mi>F</mi><msub><mi>c</mi><mtext>sky</mtext></msub>'),
  },
  fresnel: {
    text: {
      en: 'How much light water reflects depends on the angle: 2 % looking straight down, all of it at grazing incidence. The exact value comes from Snell’s law and the Fresnel equations, the mean of the two polarisations. It is computed once on the CPU into a 256-entry table, uploaded as a 1D texture, and read by the fragment shader. The plot shows that table.',
      es: 'Cuánta luz refleja el agua depende del ángulo: un 2 % mirando en vertical y toda en incidencia rasante. El valor exacto sale de la ley de Snell y de las ecuaciones de Fresnel, la media de las dos polarizaciones. Se calcula una vez en la CPU en una tabla de 256 entradas, se sube como textura 1D y la lee el fragment shader. El gráfico muestra esa tabla.',
    },
    math: m('<msub><mi>n</mi><mn>1</mn></msub><mi>sin</mi><msub><mi>θ</mi><mi>i</mi></msub><mo>=</mo><msub><mi>n</mi><mn>2</mn></msub><mi>sin</mi><msub><mi>θ</mi><mi>t</mi></msub>') + m('<mi>F</mi><mo>=</mo><mfrac><mrow><msubsup><mi>r</mi><mi>s</mi><mn>2</mn></msubsup><mo>+</mo><msubsup><mi>r</mi><mi>p</mi><mn>2</mn></msubsup></mrow><mn>2</mn></mfrac>'),
  },
  'fresnel-schlick': {
    text: {
      en: 'Schlick’s approximation replaces the Fresnel equations by one power: the reflectance at normal incidence, ((n − 1)/(n + 1))² = 0.0204 for water, plus the rest times (1 − cos θ)⁵. The plot draws both curves; they differ by at most a few hundredths. Here Fresnel is switched off, so the sea mixes sky and water half and half at every angle: compare it with the previous lesson.',
      es: 'La aproximación de Schlick sustituye las ecuaciones de Fresnel por una potencia: la reflectancia en incidencia normal, ((n − 1)/(n + 1))² = 0,0204 para el agua, más el resto por (1 − cos θ)⁵. El gráfico dibuja ambas curvas; difieren como mucho en unas centésimas. Aquí Fresnel está apagado, así que el mar mezcla cielo y agua a partes iguales en todos los ángulos: compáralo con la lección anterior.',
    },
    math: m('<mi>F</mi><mo>≈</mo><msub><mi>R</mi><mn>0</mn></msub><mo>+</mo><mo>(</mo><mn>1</mn><mo>−</mo><msub><mi>R</mi><mn>0</mn></msub><mo>)</mo><msup><mrow><mo>(</mo><mn>1</mn><mo>−</mo><mi>cos</mi><mi>θ</mi><mo>)</mo></mrow><mn>5</mn></msup>') + m('<msub><mi>R</mi><mn>0</mn></msub><mo>=</mo><msup><mrow><mo>(</mo><mfrac><mrow><mi>n</mi><mo>−</mo><mn>1</mn></mrow><mrow><mi>n</mi><mo>+</mo><mn>1</mn></mrow></mfrac><mo>)</mo></mrow><mn>2</mn></msup><mo>=</mo><mn>0.0204</mn>'),
  },
  'sun-glint': {
    text: {
      en: 'The sun’s glitter is the sun seen in countless tilted facets. Cox and Munk photographed it from the air in 1951 and found the facets’ mean-square slope σ² = 0.003 + 0.00512 U: raise the wind and the glitter widens. The shader reflects the sun through a Beckmann distribution of that σ², less the slopes the waves already draw. The sun is far brighter than a screen’s white, so the whole frame goes through one tone curve: colours below k = 0.6 stay as they are, brighter ones roll off towards white instead of clipping. Exposure scales the light before the curve, as a camera’s does: lower it and the sea darkens while the glint stays white.',
      es: 'El destello es el sol visto en incontables facetas inclinadas. Cox y Munk lo fotografiaron en 1951: la pendiente cuadrática media de las facetas es σ² = 0,003 + 0,00512 U; con más viento, el destello se ensancha. El shader refleja el sol con una distribución de Beckmann de esa σ², menos las pendientes que ya dibujan las olas. El sol brilla mucho más que el blanco de la pantalla, así que todo el cuadro pasa por una curva de tono: bajo k = 0,6 nada cambia y lo más brillante se acerca al blanco sin recortarse. La exposición escala la luz antes de la curva, como en una cámara: bájala y el mar se oscurece; el destello sigue blanco.',
    },
    math:
      m('<msup><mi>σ</mi><mn>2</mn></msup><mo>=</mo><mn>0.003</mn><mo>+</mo><mn>5.12</mn><mo>·</mo><msup><mn>10</mn><mrow><mo>−</mo><mn>3</mn></mrow></msup><mi>U</mi>') +
      m('<mi>f</mi><mo>(</mo><mi>c</mi><mo>)</mo><mo>=</mo><mi>k</mi><mo>+</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo><mo>(</mo><mn>1</mn><mo>−</mo><msup><mi>e</mi><mrow><mo>−</mo><mo>(</mo><mi>c</mi><mo>−</mo><mi>k</mi><mo>)</mo><mo>/</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo></mrow></msup><mo>)</mo>'),
  },
  'boat-twin': {
    text: {
      en: 'The GPU moves the vertices, but it cannot tell the page where the water is. So the displacement function is written twice: in GLSL for the picture and in TypeScript for the CPU, with the same phases and the same heightmaps. A test reads the shader’s heights back from the GPU and compares them with this twin. The boat floats on the twin’s heights, taken at the five points marked on its hull.',
      es: 'La GPU mueve los vértices, pero no puede decirle a la página dónde está el agua. Por eso la función de desplazamiento está escrita dos veces: en GLSL para la imagen y en TypeScript para la CPU, con las mismas fases y los mismos mapas de alturas. Una prueba lee de la GPU las alturas del shader y las compara con este gemelo. El barco flota sobre las alturas del gemelo, tomadas en los cinco puntos marcados en su casco.',
    },
    math: m('<msub><mi>M</mi><mtext>CPU</mtext></msub><mo>(</mo><mi>x</mi><mo>,</mo><mi>z</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>=</mo><msub><mi>M</mi><mtext>GPU</mtext></msub><mo>(</mo><mi>x</mi><mo>,</mo><mi>z</mi><mo>,</mo><mi>t</mi><mo>)</mo>'),
  },
  'boat-pitch': {
    text: {
      en: 'The seed’s “quiero mover el bote”: the boat samples the CPU twin at five points, marked on the hull: its centre, bow and stern half a hull length away, and both sides half a beam away. The centre gives the heave; the slope from stern to bow gives the pitch, the slope from port to starboard the roll. A damped follower smooths the result so the hull does not jitter on every ripple.',
      es: 'El “quiero mover el bote” del informe: el barco muestrea el gemelo en CPU en cinco puntos, marcados en el casco: su centro, la proa y la popa a media eslora, y ambos costados a media manga. El centro da la elevación; la pendiente de popa a proa, el cabeceo; la de babor a estribor, el balanceo. Un seguidor amortiguado suaviza el resultado para que el casco no tiemble con cada onda.',
    },
    math: m('<mi>θ</mi><mo>=</mo><mi>arctan</mi><mfrac><mrow><msub><mi>h</mi><mtext>bow</mtext></msub><mo>−</mo><msub><mi>h</mi><mtext>stern</mtext></msub></mrow><mi>L</mi></mfrac>'),
  },
  'snell-window': {
    text: {
      en: 'Seen from below, the whole sky is squeezed into a circle overhead: Snell’s window. A ray leaving water for air bends away from the normal, and beyond the critical angle, arcsin(1/1.333) = 48.6°, it cannot leave at all: it is totally reflected and you see the water’s own colour mirrored. The ring of the window moves with the waves, because each facet has its own normal.',
      es: 'Visto desde abajo, todo el cielo se comprime en un círculo sobre la cabeza: la ventana de Snell. Un rayo que pasa del agua al aire se aleja de la normal y, más allá del ángulo crítico, arcsen(1/1,333) = 48,6°, no puede salir: se refleja totalmente y se ve el color del agua reflejado. El borde de la ventana se mueve con las olas, porque cada faceta tiene su propia normal.',
    },
    math: m('<msub><mi>θ</mi><mi>c</mi></msub><mo>=</mo><mi>arcsin</mi><mfrac><msub><mi>n</mi><mtext>air</mtext></msub><msub><mi>n</mi><mtext>water</mtext></msub></mfrac><mo>=</mo><mn>48.6</mn><mo>°</mo>'),
    question: {
      ask: { en: 'Looking straight up from under the water, how wide is the circle through which you see the sky?', es: 'Mirando hacia arriba desde debajo del agua, ¿qué anchura tiene el círculo por el que se ve el cielo?' },
      answer: { en: 'A cone of half-angle 48.6° about the vertical, the critical angle arcsin(1/1.333); beyond it the surface mirrors the water.', es: 'Un cono de 48,6° de semiángulo en torno a la vertical, el ángulo crítico arcsen(1/1,333); más allá, la superficie refleja el agua.' },
    },
    references: ['hecht2017'],
  },
  'underwater-fog': {
    text: {
      en: 'Under the water, light is absorbed and scattered: red goes first, blue travels farthest. Pure water’s measured attenuation sets the ratios, nearly 10 : 1 : 0.43 for red, green and blue. The shader attenuates every colour channel by the Beer–Lambert law over the distance travelled, and fills what was lost with the water’s own colour, lighter looking up, darker looking down. Then a Gaussian blur softens the whole picture, as the seed did when the camera dives.',
      es: 'Bajo el agua la luz se absorbe y se dispersa: el rojo desaparece antes y el azul llega más lejos. La atenuación medida del agua pura fija las proporciones, casi 10 : 1 : 0,43 para rojo, verde y azul. El shader atenúa cada canal de color con la ley de Beer–Lambert según la distancia recorrida y rellena lo perdido con el color propio del agua, más claro mirando hacia arriba y más oscuro hacia abajo. Después un desenfoque gaussiano suaviza toda la imagen, como hacía el informe al sumergirse.',
    },
    math: m('<mi>T</mi><mo>(</mo><mi>d</mi><mo>)</mo><mo>=</mo><msup><mi>e</mi><mrow><mo>−</mo><mi>σ</mi><mi>d</mi></mrow></msup>') + m('<mi>c</mi><mo>=</mo><msub><mi>c</mi><mn>0</mn></msub><mi>T</mi><mo>+</mo><msub><mi>c</mi><mtext>water</mtext></msub><mo>(</mo><mn>1</mn><mo>−</mo><mi>T</mi><mo>)</mo>'),
  },
  caustics: {
    text: {
      en: 'Caustics are the bright net of light on the sea bed. Each wave is a small lens: sunlight refracted through it converges in some places and spreads in others. For every point of the bed the shader sends three nearby rays through the displaced surface and measures the area of the triangle where they land. A patch squeezed to half its area receives twice the light.',
      es: 'Las cáusticas son la red brillante de luz en el fondo. Cada ola es una pequeña lente: la luz del sol refractada converge en unos sitios y se dispersa en otros. Para cada punto del fondo el shader envía tres rayos cercanos a través de la superficie desplazada y mide el área del triángulo donde aterrizan. Un trozo comprimido a la mitad de su área recibe el doble de luz.',
    },
    math: m('<mtext>gain</mtext><mo>=</mo><mfrac><msub><mi>A</mi><mtext>surface</mtext></msub><msub><mi>A</mi><mtext>bed</mtext></msub></mfrac>'),
  },
  'god-rays': {
    text: {
      en: 'God rays are shafts of sunlight made visible by the water they cross. The shader marches along each line of sight; at every step it asks how much sunlight reaches that point, focused by the waves above, and how much of it survives the way to the eye. Everything decays exponentially with distance, so the sum is computed by constant factors per step.',
      es: 'Los rayos de luz son haces de sol que se hacen visibles en el agua que atraviesan. El shader avanza a lo largo de cada línea de visión; en cada paso pregunta cuánta luz solar llega a ese punto, enfocada por las olas de encima, y cuánta sobrevive hasta el ojo. Todo decae exponencialmente con la distancia, así que la suma se calcula con factores constantes por paso.',
    },
    math: m('<mi>L</mi><mo>=</mo><munderover><mo>∑</mo><mrow><mi>i</mi><mo>=</mo><mn>1</mn></mrow><mi>N</mi></munderover><mi>E</mi><mo>(</mo><msub><mi>p</mi><mi>i</mi></msub><mo>)</mo><mspace width="0.2em"/><msup><mi>e</mi><mrow><mo>−</mo><mi>σ</mi><msub><mi>t</mi><mi>i</mi></msub></mrow></msup><mi>Δ</mi><mi>t</mi>'),
  },
  'lod-bands': {
    text: {
      en: 'Level of detail, the seed’s optimisation: the sea is cut into square chunks, and each is drawn with fewer vertices the farther it lies from the camera. Band 0, within L, keeps every vertex; band 1, up to 2L, every second; band 2 every third, then every sixth and beyond. The colours name the bands. Raise L and the dense red area grows, and so does the triangle count.',
      es: 'Nivel de detalle, la optimización del informe: el mar se divide en parcelas cuadradas y cada una se dibuja con menos vértices cuanto más lejos está de la cámara. La banda 0, dentro de L, conserva todos los vértices; la banda 1, hasta 2L, uno de cada dos; la banda 2, uno de cada tres, y después uno de cada seis y más. Los colores nombran las bandas. Si subes L, crece la zona roja densa, y también el número de triángulos.',
    },
    math: m('<msub><mi>d</mi><mi>b</mi></msub><mo>=</mo><mi>L</mi><mspace width="0.2em"/><msup><mn>2</mn><mrow><mi>b</mi><mo>−</mo><mn>1</mn></mrow></msup>'),
  },
  'lod-morph': {
    text: {
      en: 'Where two bands meet, a sudden change of vertex spacing would make the waves pop. Geomorphing removes it: in the last part of each band, every vertex slides towards the position it will have in the coarser band, by a factor that grows from 0 to 1 with distance. At the border the two grids already agree, so the switch changes nothing on screen. Turn it off to see the pops.',
      es: 'Donde se tocan dos bandas, un cambio brusco de espaciado haría saltar las olas. El geomorfismo lo evita: en el último tramo de cada banda, cada vértice se desliza hacia la posición que tendrá en la banda más gruesa, con un factor que crece de 0 a 1 con la distancia. En el borde las dos mallas ya coinciden, y el cambio no se nota en pantalla. Apágalo para ver los saltos.',
    },
    math: m('<msup><mi>k</mi><mo>′</mo></msup><mo>=</mo><mi>k</mi><mo>+</mo><mi>f</mi><mo>(</mo><msub><mi>k</mi><mtext>coarse</mtext></msub><mo>−</mo><mi>k</mi><mo>)</mo><mo>,</mo><mspace width="0.4em"/><mi>f</mi><mo>∈</mo><mo>[</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>]</mo>'),
  },
  'frustum-culling': {
    text: {
      en: 'Frustum culling: only the chunks the camera can see are drawn. The chunks are kept in a quadtree. From the root, a node wholly outside the view frustum is skipped with everything below it, a node wholly inside is drawn without testing its children, and only nodes that straddle the border are opened. Here the selection was frozen for the usual camera and is seen from far away.',
      es: 'Frustum culling: solo se dibujan las parcelas que la cámara puede ver. Las parcelas se guardan en un quadtree. Desde la raíz, un nodo completamente fuera del frustum se descarta con todo lo que tiene debajo, uno completamente dentro se dibuja sin comprobar sus hijos, y solo se abren los nodos que cruzan el borde. Aquí la selección se congeló para la cámara habitual y se ve desde lejos.',
    },
    math: m('<mtext>outside</mtext><mo>⇔</mo><mo>∃</mo><mi>π</mi><mo>:</mo><mspace width="0.2em"/><mi>π</mi><mo>(</mo><msub><mi>p</mi><mtext>max</mtext></msub><mo>)</mo><mo>&lt;</mo><mn>0</mn>'),
  },
  'fft-calm': {
    text: {
      en: 'Beyond the seed: a sea built from the wind. A spectrum S(ω) says how much energy each wave frequency carries for a given wind speed; Pierson and Moskowitz measured it for a fully developed sea. Here U = 4 m/s, a light air: the peak wavelength is only about 14 m and the sea is low. The FFT then adds thousands of such waves, each with its own speed.',
      es: 'Más allá del informe: un mar construido a partir del viento. Un espectro S(ω) dice cuánta energía lleva cada frecuencia de ola para una velocidad de viento dada; Pierson y Moskowitz lo midieron para un mar totalmente desarrollado. Aquí U = 4 m/s, una ventolina: la longitud de onda del pico es de solo unos 14 m y el mar es bajo. La FFT suma después miles de esas olas, cada una con su propia velocidad.',
    },
    math: m('<mi>S</mi><mo>(</mo><mi>ω</mi><mo>)</mo><mo>=</mo><mfrac><mrow><mi>α</mi><msup><mi>g</mi><mn>2</mn></msup></mrow><msup><mi>ω</mi><mn>5</mn></msup></mfrac><mi>exp</mi><mrow><mo>(</mo><mo>−</mo><mi>β</mi><msup><mrow><mo>(</mo><mfrac><msub><mi>ω</mi><mn>0</mn></msub><mi>ω</mi></mfrac><mo>)</mo></mrow><mn>4</mn></msup><mo>)</mo></mrow>'),
  },
  'fft-fresh-breeze': {
    text: {
      en: 'A fresh breeze, 10 m/s: significant height about 2 m, peak wavelength about 90 m. Every wave in the spectrum moves at the speed the dispersion relation gives it, ω² = g k tanh(k h), so long waves overtake short ones and the pattern never repeats. Lower the depth and the long waves slow down. Spreading sets how closely the waves follow the wind’s direction.',
      es: 'Una brisa fresca, 10 m/s: altura significativa de unos 2 m, longitud de onda del pico de unos 90 m. Cada ola del espectro avanza a la velocidad que le da la relación de dispersión, ω² = g k tanh(k h), así que las olas largas adelantan a las cortas y el dibujo nunca se repite. Si bajas la profundidad, las olas largas se frenan. La dispersión direccional fija cuánto siguen las olas la dirección del viento.',
    },
    math: m('<msup><mi>ω</mi><mn>2</mn></msup><mo>=</mo><mi>g</mi><mi>k</mi><mi>tanh</mi><mo>(</mo><mi>k</mi><mi>h</mi><mo>)</mo>'),
  },
  'fft-short-fetch': {
    text: {
      en: 'JONSWAP is the spectrum of a young sea, measured in the North Sea: the wind has blown over a limited fetch, here 20 km at 15 m/s, so the sea is shorter and lower than a fully developed one, and its peak is sharper by the enhancement factor γ = 3.3. Raise the fetch and the peak moves to longer waves, towards Pierson–Moskowitz.',
      es: 'JONSWAP es el espectro de un mar joven, medido en el mar del Norte: el viento ha soplado sobre un fetch limitado, aquí 20 km a 15 m/s, así que el mar es más corto y más bajo que uno totalmente desarrollado, y su pico es más agudo por el factor de realce γ = 3,3. Si subes el fetch, el pico pasa a olas más largas, hacia Pierson–Moskowitz.',
    },
    math: m('<mi>S</mi><mo>=</mo><msub><mi>S</mi><mtext>PM</mtext></msub><mspace width="0.2em"/><msup><mi>γ</mi><mi>r</mi></msup><mo>,</mo><mspace width="0.4em"/><mi>r</mi><mo>=</mo><mi>exp</mi><mrow><mo>(</mo><mo>−</mo><mfrac><msup><mrow><mo>(</mo><mi>ω</mi><mo>−</mo><msub><mi>ω</mi><mi>p</mi></msub><mo>)</mo></mrow><mn>2</mn></msup><mrow><mn>2</mn><msup><mi>σ</mi><mn>2</mn></msup><msubsup><mi>ω</mi><mi>p</mi><mn>2</mn></msubsup></mrow></mfrac><mo>)</mo></mrow>'),
  },
  'fft-gale': {
    text: {
      en: 'A gale, 20 m/s. Choppiness moves points sideways towards the crests, which sharpen while the troughs widen. Where that motion folds the surface, the Jacobian of the horizontal map, or its smaller eigenvalue, drops towards zero: a wave breaks there and the shader makes foam. The foam left behind fades with the e-folding time τ = 2.5 s (below), and drifts at 3 % of the wind speed. Waves break in groups, placed by a smooth random field, so the whitecaps do not repeat with the FFT tile. From Beaufort force 7, windrows sweep the old foam into streaks along the wind. Turn Wave groups or Windrows off and look down from high above.',
      es: 'Un temporal, 20 m/s. La agudeza lleva los puntos hacia las crestas, que se afilan mientras los senos se ensanchan. Donde eso pliega la superficie, el jacobiano de la transformación horizontal, o su menor autovalor, baja hacia cero: ahí rompe una ola y el shader pone espuma. La espuma que queda se desvanece con τ = 2,5 s (abajo) y deriva al 3 % del viento. Las olas rompen en grupos, situados por un campo aleatorio suave, y la espuma no repite la tesela de la FFT. Desde la fuerza 7 de Beaufort, las hileras de Langmuir barren la espuma vieja en franjas según el viento. Apaga Grupos de olas o Hileras de espuma y mira desde muy arriba.',
    },
    math: m('<mi>J</mi><mo>=</mo><mo>(</mo><mn>1</mn><mo>+</mo><msub><mi>D</mi><mrow><mi>x</mi><mi>x</mi></mrow></msub><mo>)</mo><mo>(</mo><mn>1</mn><mo>+</mo><msub><mi>D</mi><mrow><mi>z</mi><mi>z</mi></mrow></msub><mo>)</mo><mo>−</mo><msubsup><mi>D</mi><mrow><mi>x</mi><mi>z</mi></mrow><mn>2</mn></msubsup>') +
      m('<mi>F</mi><mo>(</mo><mi>t</mi><mo>)</mo><mo>=</mo><msub><mi>F</mi><mn>0</mn></msub><mspace width="0.1em"/><msup><mi>e</mi><mrow><mo>−</mo><mi>t</mi><mo>/</mo><mi>τ</mi></mrow></msup>'),
  },
  'fft-normals': {
    text: {
      en: 'Left half: normals computed per pixel from the spectrum’s exact slopes, i k h, summed by the same FFT as the heights. Right half: the seed’s fabricated neighbours, per vertex, interpolated across each triangle. Both show the same sea. The exact normals keep detail finer than the grid; the fabricated ones lose every ripple shorter than two vertices.',
      es: 'Mitad izquierda: normales calculadas por píxel a partir de las pendientes exactas del espectro, i k h, sumadas por la misma FFT que las alturas. Mitad derecha: los vecinos fabricados del informe, por vértice, interpolados en cada triángulo. Las dos muestran el mismo mar. Las normales exactas conservan detalle más fino que la malla; las fabricadas pierden toda onda más corta que dos vértices.',
    },
    math: m('<mo>∇</mo><mi>h</mi><mo>=</mo><munder><mo>∑</mo><mi>k</mi></munder><mi>i</mi><mi>k</mi><mspace width="0.2em"/><mover><mi>h</mi><mo>~</mo></mover><mo>(</mo><mi>k</mi><mo>,</mo><mi>t</mi><mo>)</mo><msup><mi>e</mi><mrow><mi>i</mi><mi>k</mi><mo>·</mo><mi>x</mi></mrow></msup>'),
  },
  'gerstner-gentle': {
    text: {
      en: 'Gerstner waves move each point in a circle: forward under the crest, back under the trough, as water particles do. The surface is then a trochoid instead of a sine. Four waves are drawn here from the same wind spectrum, at a gentle steepness Q = 0.2: the circles are small, and the crests stay round, nearly sinusoidal.',
      es: 'Las olas de Gerstner mueven cada punto en un círculo: hacia delante bajo la cresta y hacia atrás bajo el seno, como hacen las partículas de agua. La superficie es entonces una trocoide en lugar de un seno. Aquí se dibujan cuatro olas del mismo espectro de viento, con una pendiente suave Q = 0,2: los círculos son pequeños y las crestas siguen redondas, casi sinusoidales.',
    },
    math: m('<mi>x</mi><mo>=</mo><msub><mi>x</mi><mn>0</mn></msub><mo>−</mo><munder><mo>∑</mo><mi>i</mi></munder><msub><mi>Q</mi><mi>i</mi></msub><msub><mi>A</mi><mi>i</mi></msub><msub><mover><mi>k</mi><mo>^</mo></mover><mi>i</mi></msub><mi>sin</mi><msub><mi>θ</mi><mi>i</mi></msub><mo>,</mo><mspace width="0.4em"/><mi>y</mi><mo>=</mo><munder><mo>∑</mo><mi>i</mi></munder><msub><mi>A</mi><mi>i</mi></msub><mi>cos</mi><msub><mi>θ</mi><mi>i</mi></msub>'),
  },
  'gerstner-steepness': {
    text: {
      en: 'The same sea at Q = 1, the steepest the model allows. The crests sharpen towards cusps and the troughs flatten. If the horizontal circles grew larger still, neighbouring points would overtake each other and the surface would loop through itself. The limit is Σ Qᵢ kᵢ Aᵢ ≤ 1: every wave gets the same Qᵢ, reduced when the sea is steep enough to loop.',
      es: 'El mismo mar con Q = 1, la mayor pendiente que admite el modelo. Las crestas se afilan hacia cúspides y los senos se aplanan. Si los círculos horizontales crecieran aún más, los puntos vecinos se adelantarían unos a otros y la superficie se cruzaría consigo misma. El límite es Σ Qᵢ kᵢ Aᵢ ≤ 1: todas las olas reciben el mismo Qᵢ, reducido cuando el mar es tan empinado que se cruzaría.',
    },
    math: m('<munder><mo>∑</mo><mi>i</mi></munder><msub><mi>Q</mi><mi>i</mi></msub><msub><mi>k</mi><mi>i</mi></msub><msub><mi>A</mi><mi>i</mi></msub><mo>≤</mo><mn>1</mn>'),
  },
  'compare-models': {
    text: {
      en: 'The three wave models side by side, on one camera, one wind of 10 m/s and one seed. Left, the seed’s sines and Perlin ripples; middle, 32 Gerstner trochoids drawn from the wind spectrum; right, Tessendorf’s FFT of the same spectrum. Each model draws only its strip of the screen; the dividers stand at fractions f of the part the panels leave free, from x₀ to x₁. Drag them, or move them with the arrow keys.',
      es: 'Los tres modelos de olas lado a lado, con una cámara, un viento de 10 m/s y una semilla. A la izquierda, los senos y las ondas de Perlin del informe; en el centro, 32 trocoides de Gerstner tomadas del espectro del viento; a la derecha, la FFT de Tessendorf del mismo espectro. Cada modelo dibuja solo su franja de la pantalla; los divisores están en fracciones f de la parte que dejan libre los paneles, de x₀ a x₁. Arrástralos o muévelos con las flechas.',
    },
    math: m('<msub><mi>x</mi><mtext>split</mtext></msub><mo>=</mo><mtext>round</mtext><mo>(</mo><msub><mi>x</mi><mn>0</mn></msub><mo>+</mo><mi>f</mi><mo>·</mo><mo>(</mo><msub><mi>x</mi><mn>1</mn></msub><mo>−</mo><msub><mi>x</mi><mn>0</mn></msub><mo>)</mo><mo>)</mo>'),
  },
  'physics-panel': {
    text: {
      en: 'Does the sea obey physics? The panel measures the running sea through its CPU twin: it records the height at fixed points over time, and compares the significant wave height, four times the standard deviation, and the peak period with what the spectrum predicts for this wind. It also fits the speed of waves of each length against the dispersion relation.',
      es: '¿Obedece el mar a la física? El panel mide el mar en marcha a través de su gemelo en CPU: registra la altura en puntos fijos a lo largo del tiempo y compara la altura significativa, cuatro veces la desviación típica, y el periodo de pico con lo que predice el espectro para este viento. También ajusta la velocidad de las olas de cada longitud frente a la relación de dispersión.',
    },
    math: m('<msub><mi>H</mi><mi>s</mi></msub><mo>=</mo><mn>4</mn><msqrt><msub><mi>m</mi><mn>0</mn></msub></msqrt><mo>≈</mo><mn>0.21</mn><mfrac><msubsup><mi>U</mi><mn>19.5</mn><mn>2</mn></msubsup><mi>g</mi></mfrac>'),
  },
  'kelvin-wake': {
    text: {
      en: 'A boat moving at constant speed over deep water leaves a wake confined to a wedge of half-angle arcsin(1/3) = 19.47°, whatever its speed: Kelvin’s result. The two guide lines are drawn from theory; the waves come from sources along the boat’s track, each spreading since it was left. Their cusps fall on the lines. The transverse waves behind the stern are 2πU²/g long.',
      es: 'Un barco que avanza a velocidad constante en aguas profundas deja una estela limitada a una cuña de semiángulo arcsen(1/3) = 19,47°, sea cual sea su velocidad: el resultado de Kelvin. Las dos líneas guía se dibujan desde la teoría; las olas salen de fuentes a lo largo de la derrota, cada una extendiéndose desde que quedó atrás. Sus cúspides caen sobre las líneas. Las olas transversales tras la popa miden 2πU²/g.',
    },
    math: m('<mi>α</mi><mo>=</mo><mi>arcsin</mi><mfrac><mn>1</mn><mn>3</mn></mfrac><mo>=</mo><mn>19.47</mn><mo>°</mo>') + m('<msub><mi>λ</mi><mtext>t</mtext></msub><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi><msup><mi>U</mi><mn>2</mn></msup></mrow><mi>g</mi></mfrac>'),
  },
  'wake-turn': {
    text: {
      en: 'The same boat holding a turn of 3° per second. The wake is not a fixed wedge drawn behind the hull: it is the sum of waves left at every point of the track, each one older the farther back it lies. So the wake bends with the curved track, and the guide, which assumes a straight course, no longer matches it far behind the boat.',
      es: 'El mismo barco manteniendo un giro de 3° por segundo. La estela no es una cuña fija dibujada tras el casco: es la suma de las olas dejadas en cada punto de la derrota, más antiguas cuanto más atrás. Por eso la estela se curva con la derrota, y la guía, que supone un rumbo recto, deja de coincidir con ella lejos del barco.',
    },
    math: m('<mi>η</mi><mo>(</mo><mi>x</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>=</mo><munder><mo>∑</mo><mi>j</mi></munder><mi>G</mi><mo>(</mo><mi>x</mi><mo>−</mo><msub><mi>x</mi><mi>j</mi></msub><mo>,</mo><mi>t</mi><mo>−</mo><msub><mi>t</mi><mi>j</mi></msub><mo>)</mo>'),
  },
  'waves-as-simulation': {
    text: {
      en: 'Two ways to make a sea. The spectral ocean underneath is a closed form in time: each wave of the spectrum is evaluated at any t, so the sea reaches the horizon and jumps to any moment for free, but nothing can disturb it. The rings on top are a simulation: a height field stepped every 1/60 s on a 128 m grid around the camera’s focus, with the iWave kernel that gives ω² = gk. It answers stones and the boat, but only near the camera, and to reach a moment it must run every step before it (at most 10 s of them).',
      es: 'Dos maneras de hacer un mar. El océano espectral de fondo es una fórmula cerrada en el tiempo: cada ola del espectro se evalúa en cualquier t, así que el mar llega al horizonte y salta a cualquier instante sin coste, pero nada puede perturbarlo. Los anillos de encima son una simulación: un campo de alturas que avanza cada 1/60 s en una malla de 128 m alrededor del foco de la cámara, con el núcleo de iWave que da ω² = gk. Responde a piedras y al barco, pero solo cerca de la cámara, y para llegar a un instante debe recorrer todos los pasos anteriores (como mucho 10 s).',
    },
    math:
      m('<mi>η</mi><mo>(</mo><mi mathvariant="bold">x</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>=</mo><munder><mo>∑</mo><mi mathvariant="bold">k</mi></munder><mover><mi>h</mi><mo>^</mo></mover><mo>(</mo><mi mathvariant="bold">k</mi><mo>)</mo><msup><mi>e</mi><mrow><mi>i</mi><mo>(</mo><mi mathvariant="bold">k</mi><mo>·</mo><mi mathvariant="bold">x</mi><mo>−</mo><mi>ω</mi><mi>t</mi><mo>)</mo></mrow></msup>') +
      m('<msup><mi>h</mi><mrow><mi>n</mi><mo>+</mo><mn>1</mn></mrow></msup><mo>=</mo><mn>2</mn><msup><mi>h</mi><mi>n</mi></msup><mo>−</mo><msup><mi>h</mi><mrow><mi>n</mi><mo>−</mo><mn>1</mn></mrow></msup><mo>−</mo><mfrac><mrow><mi>g</mi><mi>Δ</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mi>Δ</mi><mi>x</mi></mrow></mfrac><mo>(</mo><mi>G</mi><mo>∗</mo><msup><mi>h</mi><mi>n</mi></msup><mo>)</mo>'),
  },
  'iwave-stone': {
    text: {
      en: 'A stone dropped on a calm sea. Deep water is dispersive: a wave’s speed depends on its length, ω² = gk, so the long waves the stone made run ahead and the short ones trail, and the ring spreads into a train of crests, closer together towards the middle. Cauchy and Poisson worked out where the crests stand: at distance r after time t the waves have k = gt²/(4r²), and the crests sit where gt²/(4r) is a whole number of turns. The yellow rings are those crests, drawn from theory; the water around them is the simulation.',
      es: 'Una piedra que cae en un mar en calma. El agua profunda es dispersiva: la velocidad de una ola depende de su longitud, ω² = gk, así que las olas largas que levanta la piedra se adelantan y las cortas se quedan atrás, y el anillo se abre en un tren de crestas, más juntas hacia el centro. Cauchy y Poisson calcularon dónde están las crestas: a distancia r tras un tiempo t las olas tienen k = gt²/(4r²), y las crestas están donde gt²/(4r) es un número entero de vueltas. Los anillos amarillos son esas crestas, dibujadas desde la teoría; el agua alrededor es la simulación.',
    },
    math:
      m('<mi>k</mi><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><msup><mi>r</mi><mn>2</mn></msup></mrow></mfrac>') +
      m('<msub><mi>r</mi><mi>n</mi></msub><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mn>8</mn><mi>π</mi><mi>n</mi></mrow></mfrac>'),
  },
  'iwave-compare': {
    text: {
      en: 'The same stone twice. On the left, deep water’s equation: iWave’s kernel stands for √(−∇²), so every wavelength has its own speed and the ring spreads into a train. On the right, the plain wave equation, which most game engines use for interactive water: every wave runs at the same speed c, so the stone leaves a single ring that keeps its shape, like sound or light. A sponge along the middle keeps the two halves apart. Switch the equation to see either one alone.',
      es: 'La misma piedra dos veces. A la izquierda, la ecuación del agua profunda: el núcleo de iWave hace de √(−∇²), así que cada longitud de onda tiene su propia velocidad y el anillo se abre en un tren. A la derecha, la ecuación de ondas simple, la que usan la mayoría de los motores de juegos para el agua interactiva: todas las olas corren a la misma velocidad c, y la piedra deja un único anillo que conserva su forma, como el sonido o la luz. Una esponja en el centro separa las dos mitades. Cambia la ecuación para ver cada una sola.',
    },
    math:
      m('<mfrac><mrow><msup><mo>∂</mo><mn>2</mn></msup><mi>h</mi></mrow><mrow><mo>∂</mo><msup><mi>t</mi><mn>2</mn></msup></mrow></mfrac><mo>=</mo><mo>−</mo><mi>g</mi><msqrt><mo>−</mo><msup><mo>∇</mo><mn>2</mn></msup></msqrt><mi>h</mi><mspace width="1em"/><mo>⇒</mo><mspace width="1em"/><msup><mi>ω</mi><mn>2</mn></msup><mo>=</mo><mi>g</mi><mi>k</mi>') +
      m('<mfrac><mrow><msup><mo>∂</mo><mn>2</mn></msup><mi>h</mi></mrow><mrow><mo>∂</mo><msup><mi>t</mi><mn>2</mn></msup></mrow></mfrac><mo>=</mo><msup><mi>c</mi><mn>2</mn></msup><msup><mo>∇</mo><mn>2</mn></msup><mi>h</mi><mspace width="1em"/><mo>⇒</mo><mspace width="1em"/><mi>ω</mi><mo>=</mo><mi>c</mi><mi>k</mi>'),
  },
  'iwave-boat': {
    text: {
      en: 'The boat at 4 m/s in the interactive waves. Its waterline is a solid in the field, so waves reflect from the hull; as it moves, its bow pushes aside U·V/L cubic metres of water a second and its stern lets as much back in. Those two sources make the near-field waves, and the boat rides them. Within a distance D of the boat the field carries its waves; beyond D the analytic Kelvin wake takes over, blended over 8 m, so no wave is counted twice.',
      es: 'El barco a 4 m/s en las olas interactivas. Su línea de flotación es un sólido en el campo, así que las olas se reflejan en el casco; al avanzar, la proa aparta U·V/L metros cúbicos de agua por segundo y la popa deja volver otros tantos. Esas dos fuentes forman las olas del campo cercano, y el barco navega sobre ellas. Hasta una distancia D del barco el campo lleva sus olas; más allá, la estela analítica de Kelvin toma el relevo, mezclada a lo largo de 8 m, para no contar ninguna ola dos veces.',
    },
    math:
      m('<mi>Q</mi><mo>=</mo><mfrac><mrow><mi>U</mi><mi>V</mi></mrow><mi>L</mi></mfrac>') +
      m('<mi>D</mi><mo>=</mo><mi>max</mi><mo>(</mo><mn>2</mn><mi>L</mi><mo>,</mo><mfrac><mrow><mn>2</mn><mi>π</mi><msup><mi>U</mi><mn>2</mn></msup></mrow><mi>g</mi></mfrac><mo>)</mo>'),
  },
  horizon: {
    text: {
      en: 'Beyond the 4 km grid of chunks the sea continues to the horizon in square rings, each ring’s cells twice the size of the previous ring’s, so a triangle keeps about the same size on screen at any distance. A skirt of triangles runs out past the last ring. The waves fade out over the first rings, where the vertices lie too far apart to sample them. Far off, the air’s haze lays the horizon’s colour over the sea: its extinction is 3.912 / V for a visibility V (Koschmieder), thinning with height, so from an aircraft the sea stays clear.',
      es: 'Más allá de la malla de parcelas de 4 km, el mar sigue hasta el horizonte en anillos cuadrados, cada uno con celdas del doble de tamaño que el anterior, de modo que un triángulo mantiene en pantalla un tamaño parecido a cualquier distancia. Una falda de triángulos se extiende más allá del último anillo. Las olas se desvanecen en los primeros anillos, donde los vértices están demasiado separados para muestrearlas. A lo lejos, la calima del aire cubre el mar con el color del horizonte: su extinción es 3,912 / V para una visibilidad V (Koschmieder) y disminuye con la altura.',
    },
    math:
      m('<msub><mi>c</mi><mrow><mi>k</mi><mo>+</mo><mn>1</mn></mrow></msub><mo>=</mo><mn>2</mn><msub><mi>c</mi><mi>k</mi></msub>') +
      m('<msub><mi>β</mi><mn>0</mn></msub><mo>=</mo><mfrac><mrow><mi>ln</mi><mspace width="0.17em"/><mn>50</mn></mrow><mi>V</mi></mfrac><mo>,</mo><mspace width="0.5em"/><mi>β</mi><mo>(</mo><mi>y</mi><mo>)</mo><mo>=</mo><msub><mi>β</mi><mn>0</mn></msub><msup><mi>e</mi><mrow><mo>−</mo><mi>y</mi><mo>/</mo><mi>H</mi></mrow></msup>'),
  },
};
