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
      en: 'Level of detail, the seed’s optimisation: the sea is cut into square chunks 48 m wide, and each is drawn with fewer vertices the farther its nearest point lies from the camera, height included. Band b begins at distance d_b from the camera and keeps every s_b-th vertex: band 0, nearer than L, every vertex (2 m apart); band 1, from L, every 2nd; band 2, from 2L, every 3rd; then every 6th, 12th and 24th from 4L, 8L and 16L. The colours name the bands: red, orange, yellow, green, cyan, violet. This camera is 260 m up and L = 100 m.',
      es: 'Nivel de detalle, optimización del informe: el mar se divide en parcelas cuadradas de 48 m de lado, y cada una se dibuja con menos vértices cuanto más lejos de la cámara está su punto más cercano, altura incluida. La banda b empieza a la distancia d_b de la cámara y conserva uno de cada s_b vértices: la banda 0, a menos de L, todos (a 2 m); la banda 1, desde L, uno de cada dos; la banda 2, desde 2L, uno de cada tres; luego uno de cada 6, 12 y 24 desde 4L, 8L y 16L. Colores de las bandas: rojo, naranja, amarillo, verde, cian, violeta. Cámara a 260 m de altura, L = 100 m.',
    },
    math: m('<msub><mi>d</mi><mn>0</mn></msub><mo>=</mo><mn>0</mn><mo>,</mo><mspace width="0.4em"/><msub><mi>d</mi><mi>b</mi></msub><mo>=</mo><mi>L</mi><mspace width="0.2em"/><msup><mn>2</mn><mrow><mi>b</mi><mo>−</mo><mn>1</mn></mrow></msup><mspace width="0.4em"/><mo>(</mo><mi>b</mi><mo>≥</mo><mn>1</mn><mo>)</mo>') +
      m('<msub><mi>s</mi><mi>b</mi></msub><mo>=</mo><mn>1</mn><mo>,</mo><mn>2</mn><mo>,</mo><mn>3</mn><mo>,</mo><mn>6</mn><mo>,</mo><mn>12</mn><mo>,</mo><mn>24</mn>'),
    question: {
      ask: {
        en: 'The camera is 260 m up and L = 100 m. Will you see any red (band 0) chunks? If not, how large must L be for red to appear?',
        es: 'La cámara está a 260 m de altura y L = 100 m. ¿Verás alguna parcela roja (banda 0)? Si no, ¿cuánto debe valer L para que aparezca el rojo?',
      },
      answer: {
        en: 'No red, no orange: distance counts the camera’s height, and the bottom of the picture is about 300 m away, past 2L = 200 m, so the nearest chunks are yellow (band 2). Raise LOD distance L to about 300 m and red appears at the bottom of the view; the triangle count climbs.',
        es: 'Ni rojo ni naranja: la distancia cuenta la altura de la cámara, y el borde inferior de la imagen está a unos 300 m, más allá de 2L = 200 m, así que las parcelas más cercanas son amarillas (banda 2). Sube la distancia de LOD L hasta unos 300 m y aparece el rojo abajo; el número de triángulos sube.',
      },
    },
    choice: {
      en: 'The bands’ distances (L, doubling) and steps are a choice that keeps triangles about the same size on screen; no physics sets them.',
      es: 'Las distancias de las bandas (L, duplicándose) y sus pasos son una elección que mantiene los triángulos de tamaño parecido en pantalla; ninguna física los fija.',
    },
  },
  'lod-morph': {
    text: {
      en: 'Where two bands meet, a sudden change of vertex spacing makes the waves pop. Geomorphing (CDLOD) removes it: in a zone at the end of a band, a vertex with grid coordinate k slides in the plane to k′, towards k_c, where the coarser band’s grid puts it, by a factor f that grows linearly from 0 to 1 as its distance d crosses the zone, which starts at d_s and is w wide. At the border the grids agree: the switch changes nothing on screen. A zone spans at most half its band and, past band 0, must leave the band’s first 69 m still, so a short band gets none. Turn Geomorphing off to see the pops.',
      es: 'Donde se tocan dos bandas, un cambio brusco de espaciado hace saltar las olas. El geomorfismo (CDLOD) lo evita: en una zona al final de cada banda, un vértice de coordenada de malla k se desliza en el plano hasta k′, hacia k_c, donde lo pone la malla de la banda más gruesa, con un factor f que crece linealmente de 0 a 1 mientras su distancia d cruza la zona, que empieza en d_s y mide w. En el borde las mallas coinciden: el cambio no se nota. Una zona ocupa como mucho media banda y, pasada la banda 0, deja quietos sus primeros 69 m: una banda corta no tiene zona. Apaga el geomorfismo para ver los saltos.',
    },
    math: m('<msup><mi>k</mi><mo>′</mo></msup><mo>=</mo><mi>k</mi><mo>+</mo><mi>f</mi><mo>(</mo><msub><mi>k</mi><mi>c</mi></msub><mo>−</mo><mi>k</mi><mo>)</mo><mo>,</mo><mspace width="0.4em"/><mi>f</mi><mo>=</mo><mi>clamp</mi><mrow><mo>(</mo><mfrac><mrow><mi>d</mi><mo>−</mo><msub><mi>d</mi><mi>s</mi></msub></mrow><mi>w</mi></mfrac><mo>,</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>)</mo></mrow>'),
    question: {
      ask: {
        en: 'Here L = 40 m. With Geomorphing on, will every border between bands switch without a pop?',
        es: 'Aquí L = 40 m. Con el geomorfismo encendido, ¿cambiará cada borde entre bandas sin un salto?',
      },
      answer: {
        en: 'No. Band 1 runs only from 40 to 80 m, shorter than the 69 m (a chunk’s diagonal, 48√2 m, plus a metre) it must keep still, so it has no zone and the change from band 1 to band 2 still pops. Raise LOD distance L to 100 m and band 1 gets a zone 30 m wide.',
        es: 'No. La banda 1 va solo de 40 a 80 m, menos que los 69 m (la diagonal de una parcela, 48√2 m, más un metro) que debe dejar quietos, así que no tiene zona y el paso de la banda 1 a la 2 sigue saltando. Sube la distancia de LOD L a 100 m y la banda 1 tiene una zona de 30 m.',
      },
    },
    choice: {
      en: 'Geomorphing moves only which points of the surface the grid samples, never the surface; the zones’ widths are a choice.',
      es: 'El geomorfismo solo cambia qué puntos de la superficie muestrea la malla, nunca la superficie; el ancho de las zonas es una elección.',
    },
    references: ['strugar2009'],
  },
  'frustum-culling': {
    text: {
      en: 'Frustum culling: only chunks the camera may see are drawn. They are kept in a quadtree; each node’s box spans the sea’s lowest to highest point. Each of the frustum’s six planes π has an inward normal n and offset d. From the root, a box whose corner p⁺ farthest along n lies behind some plane is skipped with everything below it; a box whose corner p⁻ least far along n lies in front of all six is drawn without testing its children; only the others are opened, down to single chunks. The test is conservative: near the frustum’s edges an outside box may still be drawn. Here the selection, frozen for the default camera, is seen from afar.',
      es: 'Frustum culling: solo se dibujan las parcelas visibles. Se guardan en un quadtree; la caja de cada nodo va del punto más bajo del mar al más alto. Cada uno de los seis planos π del frustum tiene una normal interior n y un término d. Desde la raíz, una caja cuya esquina p⁺ más avanzada según n queda tras algún plano se descarta con todo lo de debajo; una cuya esquina p⁻ menos avanzada según n queda delante de los seis se dibuja sin mirar sus hijos; solo se abren las demás. La prueba es conservadora: cerca de los bordes puede dibujarse una caja que está fuera. Aquí la selección, congelada para la cámara habitual, se ve desde lejos.',
    },
    math: m('<mtext>skip</mtext><mo>⇐</mo><mo>∃</mo><mi>π</mi><mo>:</mo><mspace width="0.2em"/><mi>n</mi><mo>·</mo><msup><mi>p</mi><mo>+</mo></msup><mo>+</mo><mi>d</mi><mo>&lt;</mo><mn>0</mn>') +
      m('<mtext>inside</mtext><mo>⇔</mo><mo>∀</mo><mi>π</mi><mo>:</mo><mspace width="0.2em"/><mi>n</mi><mo>·</mo><msup><mi>p</mi><mo>−</mo></msup><mo>+</mo><mi>d</mi><mo>≥</mo><mn>0</mn>'),
    question: {
      ask: {
        en: 'Seen from afar, will the drawn sea end exactly at the frozen frustum’s edges, or stick out past them?',
        es: 'Visto desde lejos, ¿terminará el mar dibujado justo en los bordes del frustum congelado, o sobresaldrá de ellos?',
      },
      answer: {
        en: 'It sticks out, in steps: a chunk is drawn whole, 48 m wide, whenever any part of its box may be in view, and the box reaches the sea’s highest point and is widened by how far the waves push points sideways. Turn on Brute force to see the whole grid the culling saves.',
        es: 'Sobresale, en escalones: una parcela se dibuja entera, de 48 m, en cuanto alguna parte de su caja puede verse, y la caja llega al punto más alto del mar y se ensancha lo que las olas desplazan los puntos de lado. Activa la fuerza bruta para ver toda la malla que ahorra el recorte.',
      },
    },
    references: ['assarssonMoller2000'],
  },
  'fft-calm': {
    text: {
      en: 'Beyond the seed: a sea built from the wind. A spectrum S(ω) gives the variance of the surface’s height per unit of angular frequency ω; Pierson and Moskowitz fitted it to fully developed seas, where the wind has blown long enough over enough water. In it α = 8.1·10⁻³ and β = 0.74 are fitted constants, g is gravity and ω₀ = g/U₁₉.₅, with U₁₉.₅ = 1.026 U₁₀ the wind 19.5 m up. Here U₁₀ = 4 m/s, a gentle breeze (Beaufort 3): the peak wavelength is about 14 m and the significant height Hs = 4√m₀, m₀ = ∫S dω, only about 0.36 m. The FFT then adds thousands of waves drawn from S.',
      es: 'Más allá del informe: un mar construido a partir del viento. Un espectro S(ω) da la varianza de la altura de la superficie por unidad de frecuencia angular ω; Pierson y Moskowitz lo ajustaron a mares totalmente desarrollados, donde el viento sopló lo bastante. En él α = 8,1·10⁻³ y β = 0,74 son constantes ajustadas, g es la gravedad y ω₀ = g/U₁₉.₅, con U₁₉.₅ = 1,026 U₁₀ el viento a 19,5 m. Aquí U₁₀ = 4 m/s, una brisa débil (Beaufort 3): la longitud de onda del pico es de unos 14 m y la altura significativa Hs = 4√m₀, m₀ = ∫S dω, solo de unos 0,36 m. La FFT suma miles de olas de S.',
    },
    math: m('<mi>S</mi><mo>(</mo><mi>ω</mi><mo>)</mo><mo>=</mo><mfrac><mrow><mi>α</mi><msup><mi>g</mi><mn>2</mn></msup></mrow><msup><mi>ω</mi><mn>5</mn></msup></mfrac><mi>exp</mi><mrow><mo>(</mo><mo>−</mo><mi>β</mi><msup><mrow><mo>(</mo><mfrac><msub><mi>ω</mi><mn>0</mn></msub><mi>ω</mi></mfrac><mo>)</mo></mrow><mn>4</mn></msup><mo>)</mo></mrow><mo>,</mo><mspace width="0.4em"/><msub><mi>ω</mi><mn>0</mn></msub><mo>=</mo><mfrac><mi>g</mi><msub><mi>U</mi><mn>19.5</mn></msub></mfrac>'),
    question: {
      ask: {
        en: 'If you double the wind to 8 m/s, how much longer will the peak wave be, and how much higher the sea?',
        es: 'Si duplicas el viento a 8 m/s, ¿cuánto más larga será la ola del pico y cuánto más alto el mar?',
      },
      answer: {
        en: 'Four times each. The peak ωp is proportional to g/U, so its wavelength 2πg/ωp² grows as U², to about 56 m; m₀ grows as U⁴, so Hs grows as U², to about 1.4 m. Move Wind speed to 8 and the crests spread out.',
        es: 'Cuatro veces cada una. El pico ωp es proporcional a g/U, así que su longitud de onda 2πg/ωp² crece como U², hasta unos 56 m; m₀ crece como U⁴, así que Hs crece como U², hasta unos 1,4 m. Lleva la velocidad del viento a 8 y las crestas se separan.',
      },
    },
    references: ['piersonMoskowitz1964', 'stewart2008', 'tessendorf2001'],
  },
  'fft-fresh-breeze': {
    text: {
      en: 'A fresh breeze, U₁₀ = 10 m/s (Beaufort 5), on a fully developed Pierson–Moskowitz sea: significant height about 2.2 m, peak wavelength about 88 m. A wave of wavenumber k (2π over its wavelength) oscillates at the angular frequency ω that the dispersion relation gives it, with g gravity and h the depth. Long waves run faster (c = ω/k), so they overtake short ones and the pattern keeps changing; the whole sea repeats only after 1000 s. Lower the depth and the waves slow down, the long ones first. Directional spreading s sets how closely the waves follow the wind.',
      es: 'Una brisa fresca, U₁₀ = 10 m/s (Beaufort 5), sobre un mar de Pierson–Moskowitz totalmente desarrollado: altura significativa de unos 2,2 m, longitud de onda del pico de unos 88 m. Una ola de número de onda k (2π entre su longitud de onda) oscila a la frecuencia angular ω que le da la relación de dispersión, con g la gravedad y h la profundidad. Las olas largas corren más (c = ω/k), así que adelantan a las cortas y el dibujo cambia sin cesar; el mar entero solo se repite a los 1000 s. Si bajas la profundidad, las olas se frenan, las largas primero. La dispersión direccional s fija cuánto siguen las olas la dirección del viento.',
    },
    math: m('<msup><mi>ω</mi><mn>2</mn></msup><mo>=</mo><mi>g</mi><mi>k</mi><mi>tanh</mi><mo>(</mo><mi>k</mi><mi>h</mi><mo>)</mo>'),
    question: {
      ask: {
        en: 'Lower the water depth from deep to 10 m in your mind: will the peak waves get longer or shorter, faster or slower?',
        es: 'Imagina que bajas la profundidad de aguas profundas a 10 m: ¿las olas del pico serán más largas o más cortas, más rápidas o más lentas?',
      },
      answer: {
        en: 'Shorter and slower. Each wave keeps its ω, and tanh(kh) < 1 asks a larger k for it: the peak wave shrinks from about 88 m to about 65 m, and its speed ω/k drops from about 11.7 to 8.7 m/s. Set Water depth to 10 and watch the crests crowd.',
        es: 'Más cortas y más lentas. Cada ola conserva su ω, y tanh(kh) < 1 le pide un k mayor: la ola del pico pasa de unos 88 m a unos 65 m, y su velocidad ω/k baja de unos 11,7 a 8,7 m/s. Pon la profundidad en 10 y mira cómo se apiñan las crestas.',
      },
    },
    choice: {
      en: 'The code rounds every ω down to a multiple of 2π/1000 s, so the sea repeats exactly every 1000 s and float32 time stays precise.',
      es: 'El código redondea cada ω hacia abajo a un múltiplo de 2π/1000 s, así el mar se repite cada 1000 s exactos y el tiempo en float32 sigue preciso.',
    },
    references: ['airy1845', 'lamb1932', 'piersonMoskowitz1964', 'tessendorf2001'],
  },
  'fft-short-fetch': {
    text: {
      en: 'JONSWAP is the spectrum of a growing sea, fitted to measurements in the North Sea: the wind has blown over a limited fetch F, here 20 km at U₁₀ = 15 m/s. Its peak ωp = 22 (g²/(U₁₀F))^⅓ and its level α = 0.076 (gF/U₁₀²)^−0.22 both come from the fetch, and the peak is sharpened by γ = 3.3 with widths σ = 0.07 below ωp and 0.09 above. Here Hs is about 1.25 m and the peak wavelength about 27 m, against 5.1 m and 197 m for a fully developed sea at this wind. Raise the fetch and the peak moves to longer waves, towards Pierson–Moskowitz’s.',
      es: 'JONSWAP es el espectro de un mar en crecimiento, ajustado a medidas en el mar del Norte: el viento ha soplado sobre un fetch limitado F, aquí 20 km a U₁₀ = 15 m/s. Su pico ωp = 22 (g²/(U₁₀F))^⅓ y su nivel α = 0,076 (gF/U₁₀²)^−0,22 salen ambos del fetch, y el pico se afila con γ = 3,3 y anchos σ = 0,07 bajo ωp y 0,09 encima. Aquí Hs es de unos 1,25 m y la longitud de onda del pico de unos 27 m, frente a 5,1 m y 197 m de un mar totalmente desarrollado con este viento. Si subes el fetch, el pico pasa a olas más largas, hacia el de Pierson–Moskowitz.',
    },
    math: m('<mi>S</mi><mo>(</mo><mi>ω</mi><mo>)</mo><mo>=</mo><mfrac><mrow><mi>α</mi><msup><mi>g</mi><mn>2</mn></msup></mrow><msup><mi>ω</mi><mn>5</mn></msup></mfrac><mi>exp</mi><mrow><mo>(</mo><mo>−</mo><mfrac><mn>5</mn><mn>4</mn></mfrac><msup><mrow><mo>(</mo><mfrac><msub><mi>ω</mi><mi>p</mi></msub><mi>ω</mi></mfrac><mo>)</mo></mrow><mn>4</mn></msup><mo>)</mo></mrow><msup><mi>γ</mi><mi>r</mi></msup><mo>,</mo><mspace width="0.4em"/><mi>r</mi><mo>=</mo><mi>exp</mi><mrow><mo>(</mo><mo>−</mo><mfrac><msup><mrow><mo>(</mo><mi>ω</mi><mo>−</mo><msub><mi>ω</mi><mi>p</mi></msub><mo>)</mo></mrow><mn>2</mn></msup><mrow><mn>2</mn><msup><mi>σ</mi><mn>2</mn></msup><msubsup><mi>ω</mi><mi>p</mi><mn>2</mn></msubsup></mrow></mfrac><mo>)</mo></mrow>'),
    question: {
      ask: {
        en: 'If you raise the fetch eightfold, from 20 to 160 km, how much longer will the peak wave be?',
        es: 'Si multiplicas el fetch por ocho, de 20 a 160 km, ¿cuánto más larga será la ola del pico?',
      },
      answer: {
        en: 'About four times, to about 109 m: ωp falls as F^−⅓, so it halves, and the deep-water wavelength 2πg/ωp² quadruples. It is still short of the fully developed 197 m. Set Fetch to 160 and the crests spread out.',
        es: 'Unas cuatro veces, hasta unos 109 m: ωp baja como F^−⅓, así que se reduce a la mitad, y la longitud de onda en aguas profundas 2πg/ωp² se cuadruplica. Aún no llega a los 197 m del mar desarrollado. Pon el fetch en 160 y las crestas se separan.',
      },
    },
    choice: {
      en: 'Where the fetch would give a peak below Pierson–Moskowitz’s, the code stops ωp and α there: a joint between two fits, not a law.',
      es: 'Donde el fetch daría un pico por debajo del de Pierson–Moskowitz, el código detiene ωp y α ahí: una unión entre dos ajustes, no una ley.',
    },
    references: ['hasselmann1973', 'piersonMoskowitz1964'],
  },
  'fft-gale': {
    text: {
      en: 'A gale, U₁₀ = 20 m/s (Beaufort 8): Hs about 9 m, peak wavelength about 350 m. Choppiness λ moves points sideways towards the crests, which sharpen while the troughs widen. Where that horizontal map folds, its Jacobian J, with entries Jxx = ∂Dx/∂x, Jzz = ∂Dz/∂z and Jxz = ∂Dx/∂z of the sideways displacement D, has its determinant or its smaller eigenvalue λmin fall to zero. Below a threshold of min(det J, λmin), set so that about 10 % of the sea is breaking (Monahan’s coverage), the shader makes foam F₀. Foam left behind fades with time t (below), τ = 2.5 s, and drifts at 3 % of the wind; from Beaufort 7 windrows sweep it into streaks.',
      es: 'Un temporal, U₁₀ = 20 m/s (Beaufort 8): Hs de unos 9 m, longitud de onda del pico de unos 350 m. La agudeza λ lleva los puntos hacia las crestas, que se afilan; los senos se ensanchan. Donde esa transformación se pliega, su jacobiano J, con entradas Jxx = ∂Dx/∂x, Jzz = ∂Dz/∂z y Jxz = ∂Dx/∂z del desplazamiento D, ve anularse su determinante o su menor autovalor λmin. Bajo un umbral de min(det J, λmin), fijado para que rompa un 10 % del mar (Monahan), se forma espuma F₀. La que queda decae con el tiempo t (abajo), τ = 2,5 s, y deriva al 3 % del viento; desde Beaufort 7 las hileras la barren en franjas.',
    },
    math: m('<mi>det</mi><mi>J</mi><mo>=</mo><mo>(</mo><mn>1</mn><mo>+</mo><msub><mi>J</mi><mrow><mi>x</mi><mi>x</mi></mrow></msub><mo>)</mo><mo>(</mo><mn>1</mn><mo>+</mo><msub><mi>J</mi><mrow><mi>z</mi><mi>z</mi></mrow></msub><mo>)</mo><mo>−</mo><msubsup><mi>J</mi><mrow><mi>x</mi><mi>z</mi></mrow><mn>2</mn></msubsup>') +
      m('<msub><mi>λ</mi><mtext>min</mtext></msub><mo>=</mo><mn>1</mn><mo>+</mo><mfrac><mrow><msub><mi>J</mi><mrow><mi>x</mi><mi>x</mi></mrow></msub><mo>+</mo><msub><mi>J</mi><mrow><mi>z</mi><mi>z</mi></mrow></msub></mrow><mn>2</mn></mfrac><mo>−</mo><msqrt><msup><mrow><mo>(</mo><mfrac><mrow><msub><mi>J</mi><mrow><mi>x</mi><mi>x</mi></mrow></msub><mo>−</mo><msub><mi>J</mi><mrow><mi>z</mi><mi>z</mi></mrow></msub></mrow><mn>2</mn></mfrac><mo>)</mo></mrow><mn>2</mn></msup><mo>+</mo><msubsup><mi>J</mi><mrow><mi>x</mi><mi>z</mi></mrow><mn>2</mn></msubsup></msqrt>') +
      m('<mi>F</mi><mo>(</mo><mi>t</mi><mo>)</mo><mo>=</mo><msub><mi>F</mi><mn>0</mn></msub><mspace width="0.1em"/><msup><mi>e</mi><mrow><mo>−</mo><mi>t</mi><mo>/</mo><mi>τ</mi></mrow></msup>'),
    question: {
      ask: {
        en: 'If you raise Foam decay τ from 2.5 s to 8 s, will more whitecaps break, or will only the trails behind them last longer?',
        es: 'Si subes el decaimiento de la espuma τ de 2,5 s a 8 s, ¿romperán más olas, o solo durarán más las estelas de espuma?',
      },
      answer: {
        en: 'Only the trails: where waves break is set by the Jacobian’s threshold, which τ does not touch. Five seconds after a break, e^{−t/τ} leaves about 14 % of the foam at τ = 2.5 s and about 54 % at 8 s. Move Foam decay τ and the streaks behind the crests lengthen.',
        es: 'Solo las estelas: dónde rompen las olas lo fija el umbral del jacobiano, que τ no toca. Cinco segundos después de romper, e^{−t/τ} deja un 14 % de la espuma con τ = 2,5 s y un 54 % con 8 s. Mueve el decaimiento τ y las franjas tras las crestas se alargan.',
      },
    },
    choice: {
      en: 'The Jacobian is a stand-in for breaking, its threshold set from Monahan’s coverage; τ, the 3 % drift, the wave groups and the windrows’ pattern are chosen.',
      es: 'El jacobiano sustituye a la rotura, con su umbral fijado por la cobertura de Monahan; τ, la deriva del 3 %, los grupos de olas y las hileras son elecciones.',
    },
    references: ['tessendorf2001', 'dupuyBruneton2012', 'monahan1980', 'callaghan2012', 'piersonMoskowitz1964'],
  },
  'fft-normals': {
    text: {
      en: 'Left half: normals computed per pixel from the spectrum’s exact derivatives, summed by the same FFTs as the heights. The slopes are ∇h, with k each wave’s wavevector, h̃(k, t) its complex amplitude and x the point; the choppy displacement D’s derivatives come the same way, and the normal N is the cross product of the displaced surface P’s two tangents. Right half: the seed’s way, per vertex: neighbours 1 m away displaced and differenced, then interpolated across each triangle. Both show the same sea at 10 m/s. The exact normals keep detail finer than the grid; the vertex normals cannot show a ripple shorter than two vertex spacings.',
      es: 'Mitad izquierda: normales calculadas por píxel a partir de las derivadas exactas del espectro, sumadas por las mismas FFT que las alturas. Las pendientes son ∇h, con k el vector de onda de cada ola, h̃(k, t) su amplitud compleja y x el punto; las derivadas del desplazamiento lateral D salen igual, y la normal N es el producto vectorial de las dos tangentes de la superficie desplazada P. Mitad derecha: el método del informe, por vértice: vecinos a 1 m desplazados y restados, e interpolados en cada triángulo. Las dos muestran el mismo mar a 10 m/s. Las exactas conservan detalle más fino que la malla; las de vértice no muestran ondas más cortas que dos espaciados de vértice.',
    },
    math: m('<mo>∇</mo><mi>h</mi><mo>=</mo><munder><mo>∑</mo><mi mathvariant="bold">k</mi></munder><mi>i</mi><mi mathvariant="bold">k</mi><mspace width="0.2em"/><mover><mi>h</mi><mo>~</mo></mover><mo>(</mo><mi mathvariant="bold">k</mi><mo>,</mo><mi>t</mi><mo>)</mo><msup><mi>e</mi><mrow><mi>i</mi><mi mathvariant="bold">k</mi><mo>·</mo><mi mathvariant="bold">x</mi></mrow></msup>') +
      m('<mi>P</mi><mo>=</mo><mo>(</mo><mi>x</mi><mo>+</mo><msub><mi>D</mi><mi>x</mi></msub><mo>,</mo><mi>h</mi><mo>,</mo><mi>z</mi><mo>+</mo><msub><mi>D</mi><mi>z</mi></msub><mo>)</mo><mo>,</mo><mspace width="0.4em"/><mi>N</mi><mo>∝</mo><mfrac><mrow><mo>∂</mo><mi>P</mi></mrow><mrow><mo>∂</mo><mi>z</mi></mrow></mfrac><mo>×</mo><mfrac><mrow><mo>∂</mo><mi>P</mi></mrow><mrow><mo>∂</mo><mi>x</mi></mrow></mfrac>'),
    question: {
      ask: {
        en: 'Near the camera, will ripples a metre or two long show in the right half’s colours as they do in the left half’s?',
        es: 'Cerca de la cámara, ¿se verán en los colores de la mitad derecha las ondas de uno o dos metros, como en la izquierda?',
      },
      answer: {
        en: 'No. The right half has a normal only at each vertex, 2 m apart in the nearest band, blended across the triangles, so ripples shorter than about 4 m are lost or alias into false patterns; the left half computes each pixel’s normal. Turn Compare slope | fabricated normals off and on to see the two.',
        es: 'No. La mitad derecha tiene una normal solo en cada vértice, a 2 m en la banda más cercana, mezclada en los triángulos, así que las ondas de menos de unos 4 m se pierden o se convierten en dibujos falsos; la izquierda calcula la normal de cada píxel. Apaga y enciende Comparar normales de pendiente | fabricadas para ver las dos.',
      },
    },
    references: ['tessendorf2001'],
  },
  'gerstner-gentle': {
    text: {
      en: 'Gerstner waves move each point of the surface on a closed orbit, forward under the crest and back under the trough, as water particles do, so the surface is a trochoid instead of a sine. A point at rest position x₀ is moved by each wave i: Aᵢ is its vertical amplitude, k̂ᵢ its unit direction, θᵢ its phase there and QᵢAᵢ its horizontal amplitude, so the orbit is a circle only when Qᵢ = 1. Four waves, each 0.28 m in amplitude, three of 25 to 38 m and one of 3.9 m, are drawn here from a JONSWAP spectrum (20 m/s over 20 km) at a gentle Q = 0.2: flat ellipses, round crests, nearly sinusoidal.',
      es: 'Las olas de Gerstner mueven cada punto de la superficie en una órbita cerrada, adelante bajo la cresta y atrás bajo el seno, como las partículas de agua: la superficie es una trocoide, no un seno. Cada ola i mueve un punto de posición de reposo x₀: Aᵢ es su amplitud vertical, k̂ᵢ su dirección unitaria, θᵢ su fase allí y QᵢAᵢ su amplitud horizontal, así que la órbita solo es un círculo cuando Qᵢ = 1. Aquí hay cuatro olas de 0,28 m de amplitud, tres de 25 a 38 m y una de 3,9 m, de un espectro JONSWAP (20 m/s sobre 20 km) con una pendiente suave Q = 0,2: elipses planas, crestas redondas, casi sinusoidales.',
    },
    math: m('<mi>x</mi><mo>=</mo><msub><mi>x</mi><mn>0</mn></msub><mo>−</mo><munder><mo>∑</mo><mi>i</mi></munder><msub><mi>Q</mi><mi>i</mi></msub><msub><mi>A</mi><mi>i</mi></msub><msub><mover><mi>k</mi><mo>^</mo></mover><mi>i</mi></msub><mi>sin</mi><msub><mi>θ</mi><mi>i</mi></msub><mo>,</mo><mspace width="0.4em"/><mi>y</mi><mo>=</mo><munder><mo>∑</mo><mi>i</mi></munder><msub><mi>A</mi><mi>i</mi></msub><mi>cos</mi><msub><mi>θ</mi><mi>i</mi></msub>'),
    question: {
      ask: {
        en: 'At Q = 0.2, will a particle’s vertical excursion shrink or grow if you raise Q to 1?',
        es: 'Con Q = 0,2, ¿la excursión vertical de una partícula se reducirá o crecerá si subes Q a 1?',
      },
      answer: {
        en: 'Neither: each wave’s vertical amplitude Aᵢ stays 0.28 m. Only the horizontal one, QᵢAᵢ, grows fivefold, from 0.057 to 0.28 m, so the flat ellipses open into circles and the crests sharpen while the troughs flatten. Move Gerstner steepness Q to 1.',
        es: 'Ninguna de las dos: la amplitud vertical Aᵢ de cada ola sigue en 0,28 m. Solo la horizontal, QᵢAᵢ, se multiplica por cinco, de 0,057 a 0,28 m, así que las elipses planas se abren en círculos y las crestas se afilan mientras los senos se aplanan. Lleva la pendiente de Gerstner Q a 1.',
      },
    },
    choice: {
      en: 'Four waves of equal energy from one spectrum, and one Q shared by all, are choices made to show the trochoid; the trochoid is Gerstner’s.',
      es: 'Cuatro olas de igual energía tomadas de un espectro, y una Q común a todas, son elecciones para mostrar la trocoide; la trocoide es la de Gerstner.',
    },
    references: ['gerstner1802', 'fournierReeves1986', 'tessendorf2001', 'hasselmann1973'],
  },
  'gerstner-steepness': {
    text: {
      en: 'The same sea at Q = 1, the steepest the model allows. The crests sharpen towards cusps and the troughs flatten. Wave i, of wavenumber kᵢ = 2π over its wavelength and amplitude Aᵢ, moves a point sideways by up to QᵢAᵢ. If those motions together grew larger still, neighbouring points would overtake each other and the surface would loop through itself. That cannot happen while Σ Qᵢ kᵢ Aᵢ ≤ 1, so every wave gets the same Qᵢ = Q·min(1, 1/Σ kⱼAⱼ). Here Σ kᵢAᵢ is about 0.64, so Qᵢ = 1: circular orbits, not reduced.',
      es: 'El mismo mar con Q = 1, la mayor pendiente que admite el modelo. Las crestas se afilan hacia cúspides y los senos se aplanan. La ola i, de número de onda kᵢ = 2π entre su longitud de onda y amplitud Aᵢ, mueve un punto de lado hasta QᵢAᵢ. Si esos movimientos juntos crecieran aún más, los puntos vecinos se adelantarían unos a otros y la superficie se cruzaría consigo misma. Eso no ocurre mientras Σ Qᵢ kᵢ Aᵢ ≤ 1, así que todas las olas reciben la misma Qᵢ = Q·min(1, 1/Σ kⱼAⱼ). Aquí Σ kᵢAᵢ vale unos 0,64, así que Qᵢ = 1: órbitas circulares, sin reducir.',
    },
    math: m('<munder><mo>∑</mo><mi>i</mi></munder><msub><mi>Q</mi><mi>i</mi></msub><msub><mi>k</mi><mi>i</mi></msub><msub><mi>A</mi><mi>i</mi></msub><mo>≤</mo><mn>1</mn><mo>,</mo><mspace width="0.4em"/><msub><mi>Q</mi><mi>i</mi></msub><mo>=</mo><mi>Q</mi><mspace width="0.1em"/><mi>min</mi><mrow><mo>(</mo><mn>1</mn><mo>,</mo><mfrac><mn>1</mn><mrow><msub><mo>∑</mo><mi>j</mi></msub><msub><mi>k</mi><mi>j</mi></msub><msub><mi>A</mi><mi>j</mi></msub></mrow></mfrac><mo>)</mo></mrow>'),
    question: {
      ask: {
        en: 'At Q = 1, raise the number of Gerstner waves from 4 to 64. Will every wave keep Qᵢ = 1?',
        es: 'Con Q = 1, sube el número de olas de Gerstner de 4 a 64. ¿Conservará cada ola Qᵢ = 1?',
      },
      answer: {
        en: 'No. The same variance is shared by 64 waves, so each Aᵢ falls to about 0.07 m, but there are many more of them: Σ kᵢAᵢ grows to about 1.28, past 1, so every Qᵢ is cut to about 0.78. Orbits become ellipses and no crest loops. Move Gerstner waves to 64.',
        es: 'No. La misma varianza se reparte entre 64 olas, así que cada Aᵢ baja a unos 0,07 m, pero hay muchas más: Σ kᵢAᵢ sube a unos 1,28, más de 1, así que cada Qᵢ se recorta a unos 0,78. Las órbitas vuelven a ser elipses y ninguna cresta se cruza. Lleva las olas de Gerstner a 64.',
      },
    },
    choice: {
      en: 'Sharing one Qᵢ among all waves, like the FFT’s choppiness λ, is a choice; it guarantees no loops but is not the sea’s physics.',
      es: 'Dar la misma Qᵢ a todas las olas, como la agudeza λ de la FFT, es una elección; garantiza que no haya bucles, pero no es la física del mar.',
    },
    references: ['gerstner1802', 'tessendorf2001'],
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
