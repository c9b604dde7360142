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
  question: { ask: Record<Language, string>; answer: Record<Language, string> };
  /** One line where the quoted code is a stand-in or an artistic choice, not physics. */
  choice?: Record<Language, string>;
  /** The works behind the card (keys of BIBLIOGRAPHY in bibliography.ts). */
  references?: ReferenceKey[];
}

const m = (body: string) => `<math display="block">${body}</math>`;

export const LESSON_TEXTS: Record<string, LessonText> = {
  'flat-plane': {
    text: {
      en: 'The ocean starts as a flat grid of vertices, drawn here as a wireframe, 2 m apart near the camera. Farther out each chunk keeps fewer of them: every vertex within L = 100 m of the camera (the LOD distance control), every 2nd to 2L, every 3rd to 4L, then the step doubles each time the distance does, so far away the triangles keep roughly one size on screen. With swell and ripples at zero nothing moves: every vertex sits at P = (x, 0, z), height zero. The vertex shader computes each grid point (x, z) from its chunk’s corner and is about to ask the wave model where it goes.',
      es: 'El océano empieza como una malla plana de vértices, dibujada aquí en alambre, a 2 m unos de otros cerca de la cámara. Más lejos cada parcela conserva menos: todos hasta L = 100 m (el control de distancia LOD), uno de cada 2 hasta 2L, uno de cada 3 hasta 4L, y luego el paso se duplica con la distancia, así que a lo lejos los triángulos tienen en pantalla un tamaño parecido. Sin oleaje ni ondas nada se mueve: cada vértice está en P = (x, 0, z). El vertex shader calcula cada punto (x, z) desde la esquina de su parcela y va a preguntar al modelo de olas adónde va.',
    },
    math: m('<mi>P</mi><mo>=</mo><mo>(</mo><mi>x</mi><mo>,</mo><mn>0</mn><mo>,</mo><mi>z</mi><mo>)</mo>'),
    question: {
      ask: {
        en: 'The camera stands 45 m above the water. If you lower the LOD distance L from 100 m to 10 m, will the wireframe nearest the camera stay as dense?',
        es: 'La cámara está 45 m sobre el agua. Si bajas la distancia LOD L de 100 m a 10 m, ¿seguirá igual de densa la malla más cercana a la cámara?',
      },
      answer: {
        en: 'No. Every chunk is at least 45 m from the camera, beyond 4L = 40 m, so even the nearest keeps only every 6th vertex, 12 m apart instead of 2 m. At L = 100 m all chunks within 100 m keep every vertex. Move the LOD distance control and watch the near grid thin out.',
        es: 'No. Toda parcela está al menos a 45 m de la cámara, más allá de 4L = 40 m, así que hasta la más cercana conserva uno de cada 6 vértices: 12 m entre ellos en vez de 2. Con L = 100 m, las parcelas a menos de 100 m los conservan todos. Mueve el control de distancia LOD.',
      },
    },
    choice: {
      en: 'The bands’ distances (L, 2L, 4L…) and steps are a cost choice, not physics; the sea is a flat plane, with no Earth curvature.',
      es: 'Las distancias de las bandas (L, 2L, 4L…) y sus pasos son una elección de coste, no física; el mar es un plano, sin la curvatura de la Tierra.',
    },
  },
  'displaced-plane': {
    text: {
      en: 'The same grid, now displaced. For every vertex the shader evaluates the displacement function M(x, z, t), the sea’s height at that point and time t, and lifts the point by it: the seed’s “displacement shader”. Here M is the swell s (amplitude 1.4 m) plus the ripples r (strength 0.6 m). The grid’s vertices go to the GPU once; each frame the CPU sends only a few numbers (the swell’s phases, the ripples’ blend weight and offsets) and the GPU moves every vertex. The seed’s model only lifts points: no vertex ever moves sideways.',
      es: 'La misma malla, ahora desplazada. Para cada vértice el shader evalúa la función de desplazamiento M(x, z, t), la altura del mar en ese punto y en el instante t, y eleva el punto esa altura: el “displacement shader” del informe. Aquí M es el oleaje s (amplitud 1,4 m) más las ondas r (0,6 m). Los vértices suben a la GPU una sola vez; en cada fotograma la CPU envía solo unos números (las fases del oleaje, el peso de mezcla y los desplazamientos de las ondas) y la GPU mueve cada vértice. El modelo del informe solo eleva los puntos: ningún vértice se mueve de lado.',
    },
    math: m('<mi>P</mi><mo>=</mo><mo>(</mo><mi>x</mi><mo>,</mo><mi>M</mi><mo>(</mo><mi>x</mi><mo>,</mo><mi>z</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>,</mo><mi>z</mi><mo>)</mo>') + m('<mi>M</mi><mo>=</mo><mi>s</mi><mo>+</mo><mi>r</mi>'),
    question: {
      ask: {
        en: 'If you set the ripple strength to 0, will the wireframe turn smooth and regular, or stay bumpy?',
        es: 'Si pones la intensidad de las ondas a 0, ¿la malla se volverá suave y regular o seguirá con bultos?',
      },
      answer: {
        en: 'Smooth and regular: only the swell is left, two products of sines and cosines, the first repeating every 2π/k ≈ 126 m at k = 0.05 rad/m. The short bumps were the ripples, two noise heightmaps added on top. Move the ripple strength control.',
        es: 'Suave y regular: solo queda el oleaje, dos productos de senos y cosenos, el primero repetido cada 2π/k ≈ 126 m con k = 0,05 rad/m. Los bultos cortos eran las ondas, dos mapas de alturas de ruido sumados encima. Mueve el control de intensidad de las ondas.',
      },
    },
    choice: {
      en: 'M is the report’s choice, sines times cosines plus noise heightmaps, not a solution of the equations of water waves.',
      es: 'M es una elección del informe, senos por cosenos más mapas de alturas de ruido, no una solución de las ecuaciones de las olas.',
    },
  },
  swell: {
    text: {
      en: 'The swell is A times a sine of x times a cosine of z; a second, smaller product (0.45 A, wavenumber 1.73 k) turned by 37° breaks the egg box. The sine’s phase grows at ω = √(g k), with g = 9.81 m/s² and t the time; the cosine’s at 0.7 ω. The identity shows the product as two diagonal plane waves of wavenumber √2 k at 1.7 ω and 0.3 ω: neither has the √(g √2 k) ≈ 1.19 ω deep-water dispersion gives that length. They slide the egg box rigidly towards −x and −z; the second product slides another way, so the sum changes shape. The frequency control sets k, a wavenumber in rad/m; amplitude sets A.',
      es: 'El oleaje es A por un seno de x por un coseno de z; otro menor (0,45 A, 1,73 k), girado 37°, rompe la huevera. La fase del seno crece a ω = √(g k), con g = 9,81 m/s² y t el tiempo; la del coseno, a 0,7 ω. El producto equivale a dos ondas planas diagonales de número de onda √2 k, a 1,7 ω y 0,3 ω: ninguna tiene los √(g √2 k) ≈ 1,19 ω de la dispersión en aguas profundas. Deslizan la huevera rígida hacia −x y −z; el segundo producto, en otra dirección: la suma cambia de forma. El control de frecuencia fija k, un número de onda en rad/m; el de amplitud, A.',
    },
    math: m('<mi>h</mi><mo>=</mo><mi>A</mi><mspace width="0.2em"/><mi>sin</mi><mo>(</mo><mi>k</mi><mi>x</mi><mo>+</mo><mi>ω</mi><mi>t</mi><mo>)</mo><mspace width="0.2em"/><mi>cos</mi><mo>(</mo><mi>k</mi><mi>z</mi><mo>+</mo><mn>0.7</mn><mi>ω</mi><mi>t</mi><mo>)</mo>')
      + m('<mi>h</mi><mo>=</mo><mfrac><mi>A</mi><mn>2</mn></mfrac><mo>[</mo><mi>sin</mi><mo>(</mo><mi>k</mi><mo>(</mo><mi>x</mi><mo>+</mo><mi>z</mi><mo>)</mo><mo>+</mo><mn>1.7</mn><mi>ω</mi><mi>t</mi><mo>)</mo><mo>+</mo><mi>sin</mi><mo>(</mo><mi>k</mi><mo>(</mo><mi>x</mi><mo>−</mo><mi>z</mi><mo>)</mo><mo>+</mo><mn>0.3</mn><mi>ω</mi><mi>t</mi><mo>)</mo><mo>]</mo>')
      + m('<mi>ω</mi><mo>=</mo><msqrt><mi>g</mi><mi>k</mi></msqrt>'),
    question: {
      ask: {
        en: 'If you raise the frequency control from 0.05 to 0.2 rad/m, will the swell’s bumps travel across the sea faster or slower?',
        es: 'Si subes el control de frecuencia de 0,05 a 0,2 rad/m, ¿los bultos del oleaje cruzarán el mar más deprisa o más despacio?',
      },
      answer: {
        en: 'Slower. A bump moves ω/k = √(g/k) along x and 0.7 of that along z, about 17 m/s in all at k = 0.05 and half that, about 8.5 m/s, at 0.2. Yet, four times closer together, they pass a fixed point twice as often: ω goes from 0.70 to 1.40 rad/s. Move the frequency control.',
        es: 'Más despacio. Un bulto avanza ω/k = √(g/k) en x y 0,7 de eso en z, unos 17 m/s en total con k = 0,05 y la mitad, unos 8,5 m/s, con 0,2. Cuatro veces más juntos, pasan por un punto fijo el doble de a menudo: ω pasa de 0,70 a 1,40 rad/s. Mueve el control de frecuencia.',
      },
    },
    choice: {
      en: 'ω = √(g k) is borrowed from deep-water dispersion, but the 0.7 rate, the second product’s 0.45, 1.73 and 37° are chosen by eye: a look, not a sea.',
      es: 'ω = √(g k) viene de la dispersión en aguas profundas; el ritmo 0,7 y los 0,45, 1,73 y 37° del segundo producto, a ojo: un aspecto, no un mar.',
    },
    references: ['stewart2008'],
  },
  'swell-maximum': {
    text: {
      en: 'The swell at the top of both ranges: A = 4 m and k = 0.2 rad/m, so the first product repeats every λ = 2π/k ≈ 31 m along x and along z. Crest to trough it spans H = 2A = 8 m in those 31 m, H/λ ≈ 0.25: real water cannot hold that, deep-water waves break near H/λ ≈ 1/7. The grid’s 2 m vertices start to show along the crests. The shader counts angles in turns and keeps only the fraction, so the angle stays small however far out, then takes the sine by its own series: a GPU’s own sin is promised only to about 2⁻¹¹.',
      es: 'El oleaje en lo más alto de ambos rangos: A = 4 m y k = 0,2 rad/m, así que el primer producto se repite cada λ = 2π/k ≈ 31 m en x y en z. De cresta a valle abarca H = 2A = 8 m en esos 31 m, H/λ ≈ 0,25: el agua real no lo sostiene, las olas profundas rompen cerca de H/λ ≈ 1/7. Los vértices, a 2 m, se notan en las crestas. El shader cuenta los ángulos en vueltas y conserva solo la fracción, y el ángulo sigue pequeño por lejos que esté, y calcula el seno con su propia serie: el sin de la GPU solo se garantiza con unos 2⁻¹¹.',
    },
    math: m('<mi>λ</mi><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi></mrow><mi>k</mi></mfrac><mo>≈</mo><mn>31</mn><mspace width="0.2em"/><mtext>m</mtext>')
      + m('<mfrac><mi>H</mi><mi>λ</mi></mfrac><mo>=</mo><mfrac><mrow><mn>2</mn><mi>A</mi></mrow><mi>λ</mi></mfrac><mo>≈</mo><mn>0.25</mn><mo>&gt;</mo><mfrac><mn>1</mn><mn>7</mn></mfrac>'),
    question: {
      ask: {
        en: 'Keep k = 0.2 rad/m and lower the amplitude from 4 m to 1 m: will the crests still look as steep, and will they stand closer together?',
        es: 'Deja k = 0,2 rad/m y baja la amplitud de 4 m a 1 m: ¿seguirán las crestas igual de empinadas, y estarán más juntas?',
      },
      answer: {
        en: 'Gentler, and just as far apart. The first product’s steepest slope is A k: 0.8 (39°) at 4 m, 0.2 (11°) at 1 m, and H/λ falls to 0.064, below the 1/7 where real waves break. The spacing, 2π/k ≈ 31 m, depends on k alone. Move the amplitude control.',
        es: 'Más suaves, e igual de separadas. La pendiente máxima del primer producto es A k: 0,8 (39°) con 4 m, 0,2 (11°) con 1 m, y H/λ baja a 0,064, por debajo del 1/7 en que rompen las olas reales. La separación, 2π/k ≈ 31 m, depende solo de k. Mueve el control de amplitud.',
      },
    },
    choice: {
      en: 'The top of the ranges is a control’s limit, not a sea: at H/λ ≈ 0.25 real waves would have broken, and the seed’s sines never break.',
      es: 'Lo más alto de los rangos es un límite del control, no un mar: con H/λ ≈ 0,25 las olas reales habrían roto, y los senos del informe nunca rompen.',
    },
    references: ['deanDalrymple1991'],
  },
  'perlin-hash': {
    text: {
      en: 'The seed report calls its noise Perlin noise; what it builds, and perlinNoise.ts with it, is value noise: random values at lattice points, smoothed and interpolated, where Perlin’s own noise puts random gradients. It begins with an integer noise function n(i, j): the same lattice point (i, j) and seed always give the same value in [−1, 1), with no pattern between neighbours. The picture is n on a 16 × 16 lattice, one grey square per value (the first heightmap’s third octave). Ours hashes i, j and the seed into a 32-bit integer h with the MurmurHash3 finaliser, exact in every browser.',
      es: 'El informe llama a su ruido ruido de Perlin; lo que construye, y perlinNoise.ts con él, es ruido de valor: valores aleatorios en los puntos de una red, suavizados e interpolados, donde el ruido de Perlin pone gradientes aleatorios. Empieza con una función de ruido entera n(i, j): el mismo punto (i, j) y la misma semilla dan siempre el mismo valor en [−1, 1), sin patrón entre vecinos. La imagen es n en una red de 16 × 16, un cuadrado gris por valor (la tercera octava del primer mapa de alturas). La nuestra mezcla i, j y la semilla en un entero h de 32 bits con el finalizador de MurmurHash3, exacto en todo navegador.',
    },
    math: m('<mi>n</mi><mo>(</mo><mi>i</mi><mo>,</mo><mi>j</mi><mo>)</mo><mo>=</mo><mfrac><mi>h</mi><msup><mn>2</mn><mn>31</mn></msup></mfrac><mo>−</mo><mn>1</mn><mo>∈</mo><mo>[</mo><mo>−</mo><mn>1</mn><mo>,</mo><mn>1</mn><mo>)</mo>'),
    question: {
      ask: {
        en: 'If you change the noise seed from 1 to 2, will the squares change a few at a time, or will the whole picture become a new one?',
        es: 'Si cambias la semilla del ruido de 1 a 2, ¿cambiarán los cuadrados de a pocos o toda la imagen será otra?',
      },
      answer: {
        en: 'A new picture at once: the hash mixes the seed into every value, so the new lattice is unrelated to the old one (their correlation is near zero), and a square keeps its grey only by chance. Move the noise seed control.',
        es: 'Otra imagen de golpe: el hash mezcla la semilla en cada valor, así que la nueva red no guarda relación con la anterior (su correlación es casi cero), y un cuadrado conserva su gris solo por azar. Mueve el control de semilla del ruido.',
      },
    },
    choice: {
      en: 'The MurmurHash3 finaliser replaces the report’s hash: any well-mixed integer hash would serve; this one is exact in every JavaScript engine.',
      es: 'El finalizador de MurmurHash3 sustituye al hash del informe: serviría cualquier hash entero bien mezclado; este es exacto en todo motor de JavaScript.',
    },
    references: ['perlin1985', 'ebert2003'],
  },
  'perlin-smoothing': {
    text: {
      en: 'Step two replaces each lattice value n by a weighted mean s of its 3 × 3 neighbourhood: a quarter for the point itself, an eighth for each side (e, the sum of the four sides), a sixteenth for each corner (c, the sum of the four corners). Left, the integer noise of step one; right, the same lattice smoothed. The weights add up to one, so the values stay within [−1, 1), but their spread shrinks: for independent values the standard deviation σ falls to √(Σw²) = 3/8 of the raw one, so the greys draw towards the middle. The lattice wraps at its own period, which lets the heightmaps tile the sea without a seam.',
      es: 'El segundo paso sustituye cada valor n de la red por una media ponderada s de sus 3 × 3 vecinos: un cuarto para el propio punto, un octavo para cada lado (e, suma de los cuatro lados), un dieciseisavo para cada esquina (c, suma de las cuatro esquinas). A la izquierda, el ruido del paso uno; a la derecha, la red suavizada. Los pesos suman uno, así que los valores siguen en [−1, 1), pero se dispersan menos: para valores independientes la desviación típica σ baja a √(Σw²) = 3/8 de la original, y los grises se acercan al centro. La red se repite con su propio periodo: los mapas de alturas cubren el mar sin costuras.',
    },
    math: m('<mi>s</mi><mo>=</mo><mfrac><mi>n</mi><mn>4</mn></mfrac><mo>+</mo><mfrac><mi>e</mi><mn>8</mn></mfrac><mo>+</mo><mfrac><mi>c</mi><mn>16</mn></mfrac>')
      + m('<msub><mi>σ</mi><mi>s</mi></msub><mo>=</mo><msqrt><mfrac><mn>1</mn><mn>16</mn></mfrac><mo>+</mo><mfrac><mn>4</mn><mn>64</mn></mfrac><mo>+</mo><mfrac><mn>4</mn><mn>256</mn></mfrac></msqrt><mspace width="0.2em"/><msub><mi>σ</mi><mi>n</mi></msub><mo>=</mo><mfrac><mn>3</mn><mn>8</mn></mfrac><msub><mi>σ</mi><mi>n</mi></msub>'),
    question: {
      ask: {
        en: 'Is the right picture the left one blurred, with its dark and light patches where they were, or a new pattern?',
        es: '¿La imagen de la derecha es la de la izquierda desenfocada, con sus manchas oscuras y claras donde estaban, o un dibujo nuevo?',
      },
      answer: {
        en: 'The left one blurred: each right square is dominated by the left square at the same place (correlation 1/4 ÷ 3/8 ≈ 0.67), so dark clusters stay dark, but far fewer squares come near black or white. Change the noise seed and both pictures change together.',
        es: 'La izquierda desenfocada: cada cuadrado de la derecha depende sobre todo del de la izquierda en su lugar (correlación 1/4 ÷ 3/8 ≈ 0,67), así que las manchas oscuras siguen oscuras, pero muchos menos cuadrados se acercan al negro o al blanco. Cambia la semilla del ruido y ambas imágenes cambian a la vez.',
      },
    },
    choice: {
      en: 'Noise ripples are a stand-in for short wind waves, with no spectrum or dispersion; the 1/4, 1/8, 1/16 blur is the report’s choice.',
      es: 'Las ondas de ruido sustituyen a las olas cortas de viento, sin espectro ni dispersión; el desenfoque 1/4, 1/8, 1/16 es una elección del informe.',
    },
    references: ['ebert2003'],
  },
  'perlin-octaves': {
    text: {
      en: 'Step three interpolates between lattice points with the cosine curve (1 − cos πt)/2, flat at both ends: left, the smoothed lattice of step two, now a smooth surface. Then octaves are summed: octave o (0 to 4) is such a surface nₒ on 4·2ᵒ cells across the tile, twice the previous one’s, weighted by pᵒ with the persistence p = 0.62; the sum N is divided by the weights’ sum. Right: large soft hills with fine detail, centred on the mean N̄ and scaled to a peak of 1. That is the first heightmap H₀, 128 × 128 texels over a 96 m tile, as the vertex shader receives it.',
      es: 'El tercer paso interpola entre puntos de la red con la curva coseno (1 − cos πt)/2, plana en ambos extremos: a la izquierda, la red del paso dos, ahora una superficie suave. Después se suman octavas: la octava o (de 0 a 4) es una superficie nₒ de 4·2ᵒ celdas por mosaico, el doble que la anterior, con peso pᵒ y persistencia p = 0,62; la suma N se divide por la de los pesos. A la derecha: colinas suaves con detalle fino, centradas en la media N̄ y escaladas a un pico de 1. Es el primer mapa de alturas H₀, 128 × 128 téxeles sobre 96 m, como lo recibe el vertex shader.',
    },
    math: m('<mi>N</mi><mo>=</mo><mfrac><mrow><munderover><mo>∑</mo><mrow><mi>o</mi><mo>=</mo><mn>0</mn></mrow><mn>4</mn></munderover><msup><mi>p</mi><mi>o</mi></msup><mspace width="0.2em"/><msub><mi>n</mi><mi>o</mi></msub></mrow><mrow><munderover><mo>∑</mo><mrow><mi>o</mi><mo>=</mo><mn>0</mn></mrow><mn>4</mn></munderover><msup><mi>p</mi><mi>o</mi></msup></mrow></mfrac>')
      + m('<msub><mi>H</mi><mn>0</mn></msub><mo>=</mo><mfrac><mrow><mi>N</mi><mo>−</mo><mover><mi>N</mi><mo>¯</mo></mover></mrow><mrow><mi>max</mi><mo>|</mo><mi>N</mi><mo>−</mo><mover><mi>N</mi><mo>¯</mo></mover><mo>|</mo></mrow></mfrac>'),
    question: {
      ask: {
        en: 'The left picture is octave 2 alone. Will the right picture look like it with detail added, or will its big hills lie elsewhere?',
        es: 'La imagen de la izquierda es solo la octava 2. ¿Se parecerá la de la derecha a ella con detalle añadido, o sus colinas grandes estarán en otro sitio?',
      },
      answer: {
        en: 'Elsewhere: the big hills are octave 0, a 4 × 4 lattice of its own seed with weight 1; octave 2 enters with weight 0.62² ≈ 0.38 as medium detail, so the two pictures are only weakly alike (correlation about 0.3). Change the noise seed to see both change.',
        es: 'En otro sitio: las colinas grandes son la octava 0, una red de 4 × 4 con su propia semilla y peso 1; la octava 2 entra con peso 0,62² ≈ 0,38 como detalle medio, así que se parecen poco (correlación de unos 0,3). Cambia la semilla del ruido y cambian ambas.',
      },
    },
    choice: {
      en: 'Cosine interpolation, five octaves, persistence 0.62 and the 96 m tile are chosen by eye; real short waves follow a wind spectrum, not a persistence.',
      es: 'La interpolación coseno, cinco octavas, la persistencia 0,62 y el mosaico de 96 m se eligen a ojo; las olas cortas reales siguen un espectro de viento.',
    },
    references: ['perlin1985', 'ebert2003'],
  },
  'heightmap-blend': {
    text: {
      en: 'The vertex shader reads both heightmaps as textures (vertex texture fetch) and mixes them with a weight b = (1 − cos βt)/2 swinging between 0 and 1, β the blend speed (0.25 rad/s here, a full swing every 25 s): left H₀, right H₁, in the middle their mix now. Each map is read at p + vᵢt, p the point, so its pattern slides at 0.59 or 0.51 m/s; S is the ripple strength, 1.2 m here. The ripples change all the time, but both maps repeat every 96 m, so at any instant the ripples do too: the blend changes them in time, not in space. Set View to ocean to see the ripples alone.',
      es: 'El vertex shader lee ambos mapas de alturas como texturas (vertex texture fetch) y los mezcla con un peso b = (1 − cos βt)/2 que oscila entre 0 y 1, con β la velocidad de mezcla (aquí 0,25 rad/s: una oscilación cada 25 s): a la izquierda H₀, a la derecha H₁, en el centro su mezcla ahora. Cada mapa se lee en p + vᵢt (p, el punto): su dibujo se desliza a 0,59 o 0,51 m/s; S es la intensidad de las ondas, aquí 1,2 m. Ambos mapas se repiten cada 96 m; en cada instante, las ondas también: la mezcla las cambia en el tiempo, no en el espacio. Con Vista en ocean se ven solas.',
    },
    math: m('<mi>r</mi><mo>=</mo><mi>S</mi><mspace width="0.2em"/><mo>[</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>b</mi><mo>)</mo><msub><mi>H</mi><mn>0</mn></msub><mo>(</mo><mi>p</mi><mo>+</mo><msub><mi>v</mi><mn>0</mn></msub><mi>t</mi><mo>)</mo><mo>+</mo><mi>b</mi><msub><mi>H</mi><mn>1</mn></msub><mo>(</mo><mi>p</mi><mo>+</mo><msub><mi>v</mi><mn>1</mn></msub><mi>t</mi><mo>)</mo><mo>]</mo>')
      + m('<mi>b</mi><mo>=</mo><mfrac><mrow><mn>1</mn><mo>−</mo><mi>cos</mi><mo>(</mo><mi>β</mi><mi>t</mi><mo>)</mo></mrow><mn>2</mn></mfrac>'),
    question: {
      ask: {
        en: 'Watch the middle picture: will it ever look exactly like the left one, and how often?',
        es: 'Mira la imagen del centro: ¿llegará a ser exactamente igual a la de la izquierda, y cada cuánto?',
      },
      answer: {
        en: 'Yes, once every 2π/β ≈ 25 s: b returns to 0 and the mix is H₀ alone, then H₁ alone about 12.6 s later; the caption under it gives b. Raise the blend speed control and it comes round sooner.',
        es: 'Sí, una vez cada 2π/β ≈ 25 s: b vuelve a 0 y la mezcla es solo H₀, y unos 12,6 s después solo H₁; el rótulo de debajo da b. Sube el control de velocidad de mezcla y llega antes.',
      },
    },
    choice: {
      en: 'Two noise maps blended and drifting are an artistic stand-in for short waves: real ripples travel at their own dispersive speeds; the drifts are picked by eye.',
      es: 'Dos mapas de ruido mezclados y a la deriva son un recurso artístico: las ondas reales viajan a su velocidad dispersiva; las derivas se eligen a ojo.',
    },
  },
  'normals-wrong': {
    text: {
      en: 'The seed’s “wrong normals”: the vertices move, but each keeps the flat plane’s normal N = (0, 1, 0). Colour shows the normal, each component taken from [−1, 1] to [0, 1] (x, y, z as red, green, blue), so the whole sea is one pale green, (0.5, 1, 0.5): the lighting cannot see the waves, and only the outline against the sky moves. Switch Normals to fabricated to see the difference the next lesson explains.',
      es: 'Las “normales incorrectas” del informe: los vértices se mueven, pero cada uno conserva la normal del plano, N = (0, 1, 0). El color muestra la normal, cada componente llevada de [−1, 1] a [0, 1] (x, y, z como rojo, verde, azul), así que todo el mar es un mismo verde pálido, (0,5, 1, 0,5): la iluminación no ve las olas, y solo se mueve el contorno contra el cielo. Cambia Normales a fabricadas para ver la diferencia que explica la lección siguiente.',
    },
    math: m('<mi>N</mi><mo>=</mo><mo>(</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>,</mo><mn>0</mn><mo>)</mo>') + m('<mtext>colour</mtext><mo>=</mo><mfrac><mrow><mi>N</mi><mo>+</mo><mn>1</mn></mrow><mn>2</mn></mfrac><mo>=</mo><mo>(</mo><mn>0.5</mn><mo>,</mo><mn>1</mn><mo>,</mo><mn>0.5</mn><mo>)</mo>'),
    question: {
      ask: {
        en: 'The swell here has a 2.5 m amplitude. If you raise it to 4 m, will any colour on the sea change?',
        es: 'El oleaje tiene aquí 2,5 m de amplitud. Si la subes a 4 m, ¿cambiará algún color del mar?',
      },
      answer: {
        en: 'No: every pixel stays (0.5, 1, 0.5), because the normal never depends on M; only the outline against the sky changes. Switch Normals to fabricated and the same swell shows at once.',
        es: 'No: cada píxel sigue en (0,5, 1, 0,5), porque la normal nunca depende de M; solo cambia el contorno contra el cielo. Cambia Normales a fabricadas y el mismo oleaje aparece al instante.',
      },
    },
  },
  'normals-right': {
    text: {
      en: 'Right normals, as the seed fabricates them. Besides the vertex V1 = (x, M(x, z), z), the shader evaluates M at two invented neighbours, V2 a step Δ = 1 m along x and V3 a step Δ along z; h₁, h₂, h₃ are their heights. The two edges from V1 span a small triangle that approximates the tangent plane, and their cross product is its normal: a forward difference, exact only as Δ shrinks. Colours now change across every wave: faces tilted towards +x gain red and towards −x lose it, faces towards +z gain blue, and the steeper a face, the less green.',
      es: 'Normales correctas, como las fabrica el informe. Además del vértice V1 = (x, M(x, z), z), el shader evalúa M en dos vecinos inventados: V2, un paso Δ = 1 m en x, y V3, un paso Δ en z; h₁, h₂, h₃ son sus alturas. Las dos aristas desde V1 forman un pequeño triángulo que aproxima el plano tangente, y su producto vectorial es su normal: una diferencia hacia delante, exacta solo cuando Δ tiende a cero. Ahora los colores cambian en cada ola: las caras inclinadas hacia +x ganan rojo y hacia −x lo pierden, hacia +z ganan azul, y cuanto más empinada la cara, menos verde.',
    },
    math: m('<mi>N</mi><mo>∝</mo><mo>(</mo><msub><mi>V</mi><mn>3</mn></msub><mo>−</mo><msub><mi>V</mi><mn>1</mn></msub><mo>)</mo><mo>×</mo><mo>(</mo><msub><mi>V</mi><mn>2</mn></msub><mo>−</mo><msub><mi>V</mi><mn>1</mn></msub><mo>)</mo>')
      + m('<mi>N</mi><mo>∝</mo><mo>(</mo><mo>−</mo><mi>Δ</mi><mo>(</mo><msub><mi>h</mi><mn>2</mn></msub><mo>−</mo><msub><mi>h</mi><mn>1</mn></msub><mo>)</mo><mo>,</mo><msup><mi>Δ</mi><mn>2</mn></msup><mo>,</mo><mo>−</mo><mi>Δ</mi><mo>(</mo><msub><mi>h</mi><mn>3</mn></msub><mo>−</mo><msub><mi>h</mi><mn>1</mn></msub><mo>)</mo><mo>)</mo>'),
    question: {
      ask: {
        en: 'The swell here has a 2.5 m amplitude. If you raise it to 4 m, will the colours swing further from pale green or less?',
        es: 'El oleaje tiene aquí 2,5 m de amplitud. Si la subes a 4 m, ¿los colores se alejarán más del verde pálido o menos?',
      },
      answer: {
        en: 'Further: the swell’s slopes grow in proportion to its amplitude, so the faces tilt more, red and blue stray further from 0.5 and green drops on the steep flanks; the ripples’ fine speckle stays as it was. Move the amplitude control.',
        es: 'Más: las pendientes del oleaje crecen en proporción a su amplitud, así que las caras se inclinan más, el rojo y el azul se alejan más de 0,5 y el verde baja en los flancos empinados; el moteado fino de las ondas sigue igual. Mueve el control de amplitud.',
      },
    },
    choice: {
      en: 'The 1 m forward difference is the report’s stand-in for the exact derivative: it blurs ripples shorter than a few metres and shifts the normal half a step.',
      es: 'La diferencia hacia delante de 1 m sustituye a la derivada exacta, como en el informe: difumina ondas de pocos metros y desplaza la normal medio paso.',
    },
  },
  'sky-cube': {
    text: {
      en: 'The sky is a cube map: six square images, one per face of a cube around the camera. Here it is unfolded into a cross, seen from inside: the middle row is the horizon all round, from −x through −z (where the default camera looks) to +x and +z, with +y, the zenith, above and −y below. A unit direction d̂ is enough to look it up: the GPU picks the face whose axis d̂ points along most, and the texel. The cube keeps the square root s of each colour in 8 bits, so the shader squares what it reads. Move the sun and the six faces are painted again, not every frame.',
      es: 'El cielo es un cube map: seis imágenes cuadradas, una por cara de un cubo alrededor de la cámara. Aquí está desplegado en una cruz, visto desde dentro: la fila central es el horizonte entero, de −x pasando por −z (adonde mira la cámara por defecto) a +x y +z, con +y, el cenit, arriba y −y abajo. Basta una dirección unitaria d̂ para consultarlo: la GPU elige la cara hacia cuyo eje apunta más d̂, y el texel. El cubo guarda la raíz cuadrada s de cada color en 8 bits, así que el shader eleva al cuadrado lo que lee. Al mover el sol se vuelven a pintar las seis caras, no en cada fotograma.',
    },
    math: m('<mi>s</mi><mo>=</mo><mtext>textureLod</mtext><mo>(</mo><mtext>sky</mtext><mo>,</mo><mover><mi>d</mi><mo>^</mo></mover><mo>,</mo><mn>0</mn><mo>)</mo><mo>,</mo><mspace width="0.6em"/><mtext>color</mtext><mo>=</mo><msup><mi>s</mi><mn>2</mn></msup>'),
    choice: {
      en: 'The sky is painted, not computed from scattering in the air: a zenith-to-horizon gradient, painted clouds, and a sun disc drawn 0.99° in radius where the real one’s is 0.27°.',
      es: 'El cielo está pintado, no calculado por dispersión atmosférica: degradado del cenit al horizonte, nubes pintadas y un disco solar de 0,99° de radio; el real tiene 0,27°.',
    },
    question: {
      ask: {
        en: 'The sun stands at azimuth 20°. Set Sun azimuth to 200°: in which cell of the cross will its disc appear?',
        es: 'El sol está en el acimut 20°. Pon el acimut del sol en 200°: ¿en qué celda de la cruz aparecerá su disco?',
      },
      answer: {
        en: 'In the rightmost cell of the middle row, +z, behind the default camera. Azimuth counts clockwise from −z, so at 200° its (x, z) is along (−0.34, 0.94), and a direction shows in the face whose axis it is nearest. At 20° the disc sat in the −z cell, right of its centre.',
        es: 'En la celda derecha de la fila central, +z, detrás de la cámara por defecto. El acimut crece en sentido horario desde −z: a 200° su (x, z) va según (−0,34; 0,94), y una dirección aparece en la cara de cuyo eje está más cerca. A 20° el disco estaba en la celda −z, a la derecha del centro.',
      },
    },
    references: ['greene1986'],
  },
  reflection: {
    text: {
      en: 'A still sea is a mirror: with no swell, no ripples and roughness off, what you see is the cube map looked up along the reflected view ray. With v the unit vector from the surface to the eye and n the normal, the shader reflects −v, the ray’s own direction, into r. A ray that would point below the horizon is lifted onto it. The sky read along r, c_sky, is mixed with the water’s own colour, c_water, by the Fresnel reflectance F, which nears 1 at grazing angles: far off, the sea is almost all sky. Switch roughness on and the slopes the mesh does not show blur the reflected sky.',
      es: 'Un mar en calma es un espejo: sin oleaje, sin ondas y sin rugosidad, lo que se ve es el cube map consultado en la dirección del rayo de vista reflejado. Con v el vector unitario de la superficie hacia el ojo y n la normal, el shader refleja −v, la dirección del propio rayo, en r. Un rayo que apuntaría bajo el horizonte se levanta hasta él. El cielo leído en r, c_sky, se mezcla con el color propio del agua, c_water, según la reflectancia de Fresnel F, que tiende a 1 en incidencia rasante: a lo lejos, el mar es casi todo cielo. Activa la rugosidad y las pendientes que la malla no muestra desenfocan el cielo reflejado.',
    },
    math: m('<mi>r</mi><mo>=</mo><mo>−</mo><mi>v</mi><mo>+</mo><mn>2</mn><mo>(</mo><mi>v</mi><mo>·</mo><mi>n</mi><mo>)</mo><mi>n</mi>') + m('<mi>c</mi><mo>=</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>F</mi><mo>)</mo><msub><mi>c</mi><mtext>water</mtext></msub><mo>+</mo><mi>F</mi><msub><mi>c</mi><mtext>sky</mtext></msub>'),
    choice: {
      en: 'Lifting r onto the horizon is a choice: the sea reflects only the sky cube, never other waves, the boat or itself.',
      es: 'Levantar r hasta el horizonte es una elección: el mar solo refleja el cubo del cielo, nunca otras olas, el barco ni a sí mismo.',
    },
    question: {
      ask: {
        en: 'Switch Fresnel off. Will the sea near the camera get paler or darker, and the sea near the horizon?',
        es: 'Apaga Fresnel. ¿El mar cerca de la cámara se aclarará o se oscurecerá? ¿Y el mar cerca del horizonte?',
      },
      answer: {
        en: 'Off, the shader uses F = 0.5 at every angle. Near the camera, where the true F is well below one half, the sea turns paler, half sky; near the horizon, where F is close to 1, it darkens to half water. Switch Fresnel on again to compare.',
        es: 'Apagado, el shader usa F = 0,5 en todos los ángulos. Cerca de la cámara, donde la F real queda muy por debajo de un medio, el mar se aclara, mitad cielo; cerca del horizonte, donde F es casi 1, se oscurece hasta ser mitad agua. Vuelve a activar Fresnel para comparar.',
      },
    },
    references: ['blinnNewell1976', 'greene1986', 'hecht2017'],
  },
  fresnel: {
    text: {
      en: 'Water’s reflectance depends on the angle of incidence θi, from the normal: 2 % looking straight down, all at grazing incidence. Snell’s law gives the angle θt of the ray that enters, from n₁ = 1 (air) and n₂ = 1.333 (water); the Fresnel equations give the amplitude ratios r_s and r_p of the two polarisations, and unpolarised light reflects the mean of their squares, F. The CPU tabulates F once, 256 entries by cos θi, uploaded as a 256 × 1 float texture (WebGL2 has no 1D textures); the fragment shader reads two entries with texelFetch and interpolates by hand, since float textures are not always filterable. The plot shows that table.',
      es: 'La reflectancia del agua depende del ángulo de incidencia θi, desde la normal: un 2 % en vertical, toda en incidencia rasante. La ley de Snell da el ángulo θt del rayo que entra, con los índices n₁ = 1 (aire) y n₂ = 1,333 (agua); las ecuaciones de Fresnel dan los cocientes de amplitud r_s y r_p de las dos polarizaciones; la luz no polarizada refleja la media de sus cuadrados, F. La CPU tabula F una vez, 256 entradas por cos θi, como textura float de 256 × 1 (WebGL2 no tiene texturas 1D); el fragment shader lee dos con texelFetch e interpola a mano: las texturas float no siempre se filtran. El gráfico muestra esa tabla.',
    },
    math: m('<msub><mi>n</mi><mn>1</mn></msub><mi>sin</mi><msub><mi>θ</mi><mi>i</mi></msub><mo>=</mo><msub><mi>n</mi><mn>2</mn></msub><mi>sin</mi><msub><mi>θ</mi><mi>t</mi></msub>') + m('<mi>F</mi><mo>=</mo><mfrac><mrow><msubsup><mi>r</mi><mi>s</mi><mn>2</mn></msubsup><mo>+</mo><msubsup><mi>r</mi><mi>p</mi><mn>2</mn></msubsup></mrow><mn>2</mn></mfrac>'),
    question: {
      ask: {
        en: 'Before reading the plot: at 60° from the vertical, is water’s reflectance nearer 6 %, 25 % or 50 %?',
        es: 'Antes de mirar el gráfico: a 60° de la vertical, ¿la reflectancia del agua está más cerca del 6 %, del 25 % o del 50 %?',
      },
      answer: {
        en: 'About 6 %: the curve stays low up to 60° (0.060 there) and climbs steeply only past 75°, reaching one half near 84° and 1 at 90°. That is why the near sea shows the water’s colour and the far sea the sky. Fresnel plot draws it.',
        es: 'Cerca del 6 %: la curva sigue baja hasta 60° (0,060 ahí) y solo sube con fuerza pasados 75°: llega a un medio cerca de 84° y a 1 en 90°. Por eso el mar cercano muestra el color del agua y el lejano el cielo. El gráfico de Fresnel lo dibuja.',
      },
    },
    references: ['hecht2017'],
  },
  'fresnel-schlick': {
    text: {
      en: 'Schlick’s approximation replaces the Fresnel equations by one power of the angle of incidence θ: the reflectance at normal incidence, R₀ = ((n − 1)/(n + 1))² = 0.0204 for water’s index n = 1.333, plus the rest, 1 − R₀, times (1 − cos θ)⁵. The plot draws both curves. They agree at 0° and at 90°, not between: the largest difference, 0.059, lies near 84°, where Schlick gives 0.574 and the exact table 0.515. The shader never uses Schlick. Here Fresnel is switched off, so the sea mixes sky and water with a constant F = 0.5 at every angle, the sun’s glint too: compare it with the previous lesson.',
      es: 'La aproximación de Schlick sustituye las ecuaciones de Fresnel por una potencia del ángulo de incidencia θ: la reflectancia en incidencia normal, R₀ = ((n − 1)/(n + 1))² = 0,0204 para el índice del agua n = 1,333, más el resto, 1 − R₀, por (1 − cos θ)⁵. El gráfico dibuja ambas curvas. Coinciden en 0° y en 90°, no entre medias: la mayor diferencia, 0,059, está cerca de 84°, donde Schlick da 0,574 y la tabla exacta 0,515. El shader nunca usa Schlick. Aquí Fresnel está apagado, así que el mar mezcla cielo y agua con una F constante de 0,5 en todos los ángulos, también en el destello del sol: compáralo con la lección anterior.',
    },
    math: m('<mi>F</mi><mo>≈</mo><msub><mi>R</mi><mn>0</mn></msub><mo>+</mo><mo>(</mo><mn>1</mn><mo>−</mo><msub><mi>R</mi><mn>0</mn></msub><mo>)</mo><msup><mrow><mo>(</mo><mn>1</mn><mo>−</mo><mi>cos</mi><mi>θ</mi><mo>)</mo></mrow><mn>5</mn></msup>') + m('<msub><mi>R</mi><mn>0</mn></msub><mo>=</mo><msup><mrow><mo>(</mo><mfrac><mrow><mi>n</mi><mo>−</mo><mn>1</mn></mrow><mrow><mi>n</mi><mo>+</mo><mn>1</mn></mrow></mfrac><mo>)</mo></mrow><mn>2</mn></msup><mo>=</mo><mn>0.0204</mn>'),
    choice: {
      en: 'Fresnel off is a teaching switch: the constant F = 0.5 is no physical value; it shows what the angle dependence adds.',
      es: 'Fresnel apagado es un interruptor didáctico: la F constante de 0,5 no es un valor físico; muestra lo que añade la dependencia del ángulo.',
    },
    question: {
      ask: {
        en: 'Where will the two curves on the plot lie farthest apart: at normal incidence, at 60°, or near grazing?',
        es: '¿Dónde estarán más separadas las dos curvas del gráfico: en incidencia normal, a 60° o cerca de la incidencia rasante?',
      },
      answer: {
        en: 'Near grazing, at about 84°: Schlick lies 0.059 above the exact reflectance there (0.574 against 0.515). At 0° both give R₀ = 0.0204 and at 90° both give 1; at 60° they differ by less than 0.01. Fresnel plot shows both curves.',
        es: 'Cerca de la incidencia rasante, hacia 84°: ahí Schlick queda 0,059 por encima de la reflectancia exacta (0,574 frente a 0,515). En 0° ambas dan R₀ = 0,0204 y en 90° ambas dan 1; a 60° difieren en menos de 0,01. El gráfico de Fresnel muestra las dos curvas.',
      },
    },
    references: ['schlick1994', 'hecht2017'],
  },
  'sun-glint': {
    text: {
      en: 'The sun’s glitter is the sun seen in countless tilted facets. Cox and Munk photographed it from the air in 1951 and found the facets’ mean-square slope σ² = 0.003 + 0.00512 U, with U the wind speed in m/s 12.5 m above the sea (the Wind speed slider, 10 m up, is converted): raise the wind and the glitter widens. The shader reflects the sun through a Beckmann distribution of that σ², less the slopes the waves already draw. The sun is far brighter than a screen’s white, so each colour channel c, after exposure, goes through one tone curve f: below k = 0.6 it stays as it is, above it rolls off towards white instead of clipping.',
      es: 'El destello es el sol visto en incontables facetas inclinadas. Cox y Munk lo fotografiaron desde el aire en 1951: la pendiente cuadrática media de las facetas es σ² = 0,003 + 0,00512 U, con U el viento en m/s a 12,5 m sobre el mar (el control, a 10 m, se convierte): con más viento, el destello se ensancha. El shader refleja el sol con una distribución de Beckmann de esa σ², menos las pendientes que ya dibujan las olas. El sol brilla mucho más que el blanco de la pantalla: cada canal de color c, tras la exposición, pasa por una curva de tono f; bajo k = 0,6 no cambia, encima se acerca al blanco sin recortarse.',
    },
    math:
      m('<msup><mi>σ</mi><mn>2</mn></msup><mo>=</mo><mn>0.003</mn><mo>+</mo><mn>5.12</mn><mo>·</mo><msup><mn>10</mn><mrow><mo>−</mo><mn>3</mn></mrow></msup><mi>U</mi>') +
      m('<mi>f</mi><mo>(</mo><mi>c</mi><mo>)</mo><mo>=</mo><mi>c</mi><mspace width="0.3em"/><mtext>if</mtext><mspace width="0.3em"/><mi>c</mi><mo>≤</mo><mi>k</mi><mo>;</mo><mspace width="0.6em"/><mi>f</mi><mo>(</mo><mi>c</mi><mo>)</mo><mo>=</mo><mi>k</mi><mo>+</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo><mo>(</mo><mn>1</mn><mo>−</mo><msup><mi>e</mi><mrow><mo>−</mo><mo>(</mo><mi>c</mi><mo>−</mo><mi>k</mi><mo>)</mo><mo>/</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo></mrow></msup><mo>)</mo><mspace width="0.3em"/><mtext>if</mtext><mspace width="0.3em"/><mi>c</mi><mo>&gt;</mo><mi>k</mi>'),
    choice: {
      en: 'The tone curve’s knee k = 0.6 and its exponential shoulder are a display choice; Cox and Munk’s slopes are measured, Beckmann’s facets a model of them.',
      es: 'El codo k = 0,6 y el hombro exponencial de la curva de tono son una elección; las pendientes de Cox y Munk son medidas, y Beckmann, su modelo.',
    },
    question: {
      ask: {
        en: 'Raise Wind speed from 5 to 15 m/s: will the path of glitter get wider or narrower?',
        es: 'Sube la velocidad del viento de 5 a 15 m/s: ¿el camino de destellos se hará más ancho o más estrecho?',
      },
      answer: {
        en: 'Wider: Cox and Munk’s σ² grows from 0.029 to 0.081 (the wind taken to 12.5 m), so facets tilted farther from the mirror direction still send you the sun. The same sunlight spreads over more sea, so each part of the path is dimmer, though its core may stay white through the tone curve.',
        es: 'Más ancho: la σ² de Cox y Munk pasa de 0,029 a 0,081 (el viento llevado a 12,5 m), así que facetas más inclinadas respecto del espejo aún te envían el sol. La misma luz cubre más mar: cada parte del camino es más tenue, aunque su núcleo puede seguir blanco tras la curva de tono.',
      },
    },
    references: ['coxMunk1954', 'bruneton2010', 'walter2007', 'reinhard2002'],
  },
  'boat-twin': {
    text: {
      en: 'The GPU moves the vertices, but reading its heights back every frame would make the page wait for it. So the displacement function M is written twice: in GLSL for the picture and in TypeScript for the CPU. The phases φ₁…φ₄ are computed once a frame on the CPU, in double precision, and handed to both; the ripples come from the same heightmaps. A browser test reads the shader’s heights back from the GPU and finds them within 0.03 mm of this twin at the default parameters. The boat floats on the twin’s heights, taken at the five points marked on its hull. In the swell, A is the amplitude, k the wavenumber, (u, v) the axes turned by 37°.',
      es: 'La GPU mueve los vértices, pero leer sus alturas en cada fotograma haría esperar a la página. Por eso la función de desplazamiento M se escribe dos veces: en GLSL para la imagen y en TypeScript para la CPU. La CPU calcula las fases φ₁…φ₄ una vez por fotograma, en doble precisión, para ambas; las ondas salen de los mismos mapas de alturas. Una prueba lee de la GPU las alturas del shader: difieren menos de 0,03 mm de este gemelo con los parámetros por defecto. El barco flota sobre las alturas del gemelo, en los cinco puntos marcados en su casco. En el oleaje, A es la amplitud, k el número de onda, (u, v) los ejes girados 37°.',
    },
    math:
      m('<msub><mi>h</mi><mtext>swell</mtext></msub><mo>=</mo><mi>A</mi><mo>[</mo><mi>sin</mi><mo>(</mo><mi>k</mi><mi>x</mi><mo>+</mo><msub><mi>φ</mi><mn>1</mn></msub><mo>)</mo><mi>cos</mi><mo>(</mo><mi>k</mi><mi>z</mi><mo>+</mo><msub><mi>φ</mi><mn>2</mn></msub><mo>)</mo><mo>+</mo><mn>0.45</mn><mspace width="0.1em"/><mi>sin</mi><mo>(</mo><mn>1.73</mn><mi>k</mi><mi>u</mi><mo>+</mo><msub><mi>φ</mi><mn>3</mn></msub><mo>)</mo><mi>cos</mi><mo>(</mo><mn>1.73</mn><mi>k</mi><mi>v</mi><mo>+</mo><msub><mi>φ</mi><mn>4</mn></msub><mo>)</mo><mo>]</mo>') +
      m('<msub><mi>M</mi><mtext>CPU</mtext></msub><mo>(</mo><mi>x</mi><mo>,</mo><mi>z</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>≈</mo><msub><mi>M</mi><mtext>GPU</mtext></msub><mo>(</mo><mi>x</mi><mo>,</mo><mi>z</mi><mo>,</mo><mi>t</mi><mo>)</mo>'),
    question: {
      ask: {
        en: 'Raise Float response time from 0.25 s to 2 s: how far can the boat fall behind the water it floats on?',
        es: 'Sube el tiempo de respuesta de la flotación de 0,25 s a 2 s: ¿cuánto puede quedarse atrás el barco respecto del agua en que flota?',
      },
      answer: {
        en: 'Not far: it follows more slowly, a critically damped spring with ω = 1/response, but its heave is held within 0.2 m of the twin’s height at the hull’s centre and its pitch and roll within 0.08 rad (4.6°) of the surface’s. It lags and smooths, but never sinks or flies.',
        es: 'Poco: sigue más despacio, como un resorte con amortiguamiento crítico de ω = 1/respuesta, pero su elevación se mantiene a menos de 0,2 m de la altura del gemelo en el centro del casco, y su cabeceo y balanceo a menos de 0,08 rad (4,6°) de los de la superficie. Se retrasa y suaviza, pero nunca se hunde ni vuela.',
      },
    },
  },
  'boat-pitch': {
    text: {
      en: 'The seed’s “Quiero mover el bote”: the boat samples the CPU twin at five points, marked on the hull: its centre, the bow and stern half a hull length L away, and both sides half a beam B away. The centre’s height gives the heave; the height difference from stern to bow over L gives the pitch θ, the difference from port to starboard over B the roll φ, divided by √(1 + tan²θ) so that on a tilted plane the hull’s up axis is exactly its normal. A critically damped follower then smooths all three, so the hull does not jitter on every ripple.',
      es: 'El “Quiero mover el bote” del informe: el barco muestrea el gemelo en CPU en cinco puntos, marcados en el casco: su centro, la proa y la popa a media eslora L, y ambos costados a media manga B. La altura del centro da la elevación; la diferencia de altura de popa a proa entre L da el cabeceo θ, y la de babor a estribor entre B, el balanceo φ, dividida por √(1 + tan²θ) para que sobre un plano inclinado el eje vertical del casco sea justo su normal. Después un seguidor con amortiguamiento crítico suaviza los tres, para que el casco no tiemble con cada onda.',
    },
    math:
      m('<mi>θ</mi><mo>=</mo><mi>arctan</mi><mfrac><mrow><msub><mi>h</mi><mtext>bow</mtext></msub><mo>−</mo><msub><mi>h</mi><mtext>stern</mtext></msub></mrow><mi>L</mi></mfrac>') +
      m('<mi>φ</mi><mo>=</mo><mi>arctan</mi><mfrac><mrow><msub><mi>h</mi><mtext>starboard</mtext></msub><mo>−</mo><msub><mi>h</mi><mtext>port</mtext></msub></mrow><mrow><mi>B</mi><msqrt><mn>1</mn><mo>+</mo><msup><mi>tan</mi><mn>2</mn></msup><mi>θ</mi></msqrt></mrow></mfrac>'),
    choice: {
      en: 'The damped follower is a choice, not hydrostatics: the boat has no buoyancy, mass or natural period, and stays within 0.2 m and 4.6° of the surface’s pose.',
      es: 'El seguidor amortiguado es una elección, no hidrostática: el barco no tiene flotabilidad, masa ni periodo propio, y queda a menos de 0,2 m y 4,6° de la superficie.',
    },
    question: {
      ask: {
        en: 'Halve Swell amplitude, from 1.6 m to 0.8 m: will the boat’s largest pitch halve, shrink less, or shrink more?',
        es: 'Reduce a la mitad la amplitud del oleaje, de 1,6 m a 0,8 m: ¿el mayor cabeceo del barco se reducirá a la mitad, menos o más?',
      },
      answer: {
        en: 'About halve: the pitch is the arctangent of the bow-minus-stern height over L, and for slopes this small (under 0.35) the arctangent is nearly the slope itself, which is proportional to A. The ripples, which do not change, keep a small part of the motion.',
        es: 'Más o menos a la mitad: el cabeceo es el arcotangente de la diferencia de altura entre proa y popa dividida por L, y para pendientes tan pequeñas (menos de 0,35) el arcotangente es casi la pendiente misma, proporcional a A. Las ondas, que no cambian, conservan una pequeña parte del movimiento.',
      },
    },
  },
  'snell-window': {
    text: {
      en: 'Seen from below, the whole sky is squeezed into a circle overhead: Snell’s window. A ray leaving water (n_water = 1.333) for air (n_air = 1) bends away from the normal; beyond the critical angle θc = arcsin(1/1.333) = 48.6° it cannot leave at all: it is totally reflected, and you see the water’s own colour mirrored. So the sky’s whole hemisphere fits in a cone 97° across. Inside it the reflectance from below climbs from 2 % overhead to 1 at the rim, so the sky dims towards the edge. The rim moves with the waves, because each facet has its own normal.',
      es: 'Visto desde abajo, todo el cielo se comprime en un círculo sobre la cabeza: la ventana de Snell. Un rayo que pasa del agua (n_water = 1,333) al aire (n_air = 1) se aleja de la normal; más allá del ángulo crítico θc = arcsen(1/1,333) = 48,6° no puede salir: se refleja totalmente y se ve el color propio del agua reflejado. Así, todo el hemisferio del cielo cabe en un cono de 97°. Dentro, la reflectancia desde abajo sube del 2 % en la vertical a 1 en el borde, y el cielo se oscurece hacia él. El borde se mueve con las olas, porque cada faceta tiene su propia normal.',
    },
    math: m('<msub><mi>θ</mi><mi>c</mi></msub><mo>=</mo><mi>arcsin</mi><mfrac><msub><mi>n</mi><mtext>air</mtext></msub><msub><mi>n</mi><mtext>water</mtext></msub></mfrac><mo>=</mo><mn>48.6</mn><mo>°</mo>'),
    choice: {
      en: 'Outside the window, what the surface mirrors is the fog’s painted colour for that direction, not a true reflection of the sea bed or the boat.',
      es: 'Fuera de la ventana, lo que refleja la superficie es el color pintado de la niebla en esa dirección, no un reflejo real del fondo ni del barco.',
    },
    question: {
      ask: {
        en: 'Switch Fresnel off: will the rim of the window get sharper or softer?',
        es: 'Apaga Fresnel: ¿el borde de la ventana se hará más nítido o más suave?',
      },
      answer: {
        en: 'Sharper. Off, the shader shows all sky inside θc and all mirrored water outside: a step. On, the reflectance from below climbs steeply just before 48.6°, so the sky dims and fades into the mirrored water over the last few degrees.',
        es: 'Más nítido. Apagado, el shader muestra todo cielo dentro de θc y todo agua reflejada fuera: un escalón. Encendido, la reflectancia desde abajo sube con fuerza justo antes de 48,6°, así que el cielo se oscurece y se funde con el agua reflejada en los últimos grados.',
      },
    },
    references: ['hecht2017'],
  },
  'underwater-fog': {
    text: {
      en: 'Under the water, light is absorbed and scattered: red goes first, blue travels farthest. Pure water’s measured beam attenuation sets the ratios ε, 9.7 : 1 : 0.43 for red, green and blue; Water fog density σ is green’s attenuation per metre (0.035 is pure water, this view sets 0.06). The shader attenuates each channel by the Beer–Lambert law over the distance d travelled, and fills what was lost with the water’s own colour c_water, lighter looking up, darker looking down; c₀ is the colour behind the water. Then a Gaussian blur softens the whole picture, as the seed did when the camera dives.',
      es: 'Bajo el agua la luz se absorbe y se dispersa: el rojo desaparece antes y el azul llega más lejos. La atenuación medida del agua pura fija las proporciones ε, 9,7 : 1 : 0,43 para rojo, verde y azul; la densidad de niebla σ es la atenuación del verde por metro (0,035 es agua pura; esta vista pone 0,06). El shader atenúa cada canal con la ley de Beer–Lambert según la distancia recorrida d y rellena lo perdido con el color propio del agua c_water, más claro mirando hacia arriba y más oscuro hacia abajo; c₀ es el color detrás del agua. Después un desenfoque gaussiano suaviza toda la imagen, como hacía el informe al sumergirse.',
    },
    math: m('<mi>T</mi><mo>(</mo><mi>d</mi><mo>)</mo><mo>=</mo><msup><mi>e</mi><mrow><mo>−</mo><mi>σ</mi><mi>ε</mi><mi>d</mi></mrow></msup>') + m('<mi>c</mi><mo>=</mo><msub><mi>c</mi><mn>0</mn></msub><mi>T</mi><mo>+</mo><msub><mi>c</mi><mtext>water</mtext></msub><mo>(</mo><mn>1</mn><mo>−</mo><mi>T</mi><mo>)</mo>'),
    choice: {
      en: 'Only the ratios ε are measured; the water’s own colour, from 0.22 looking down to 1 looking up, and the blur are painted choices.',
      es: 'Solo las proporciones ε son medidas; el color propio del agua, de 0,22 mirando abajo a 1 mirando arriba, y el desenfoque son elecciones pintadas.',
    },
    question: {
      ask: {
        en: 'At this view’s density, 0.06 per metre, will things 10 m away look only dimmer, or also bluer-green?',
        es: 'Con la densidad de esta vista, 0,06 por metro, ¿lo que está a 10 m se verá solo más tenue o también más azul verdoso?',
      },
      answer: {
        en: 'Bluer-green: over 10 m red keeps 0.3 % of its light, green 55 % and blue 77 %. Halve Water fog density and the same loss of red takes 20 m.',
        es: 'Más azul verdoso: en 10 m el rojo conserva el 0,3 % de su luz, el verde el 55 % y el azul el 77 %. Reduce a la mitad la densidad de niebla y esa misma pérdida de rojo necesita 20 m.',
      },
    },
    references: ['popeFry1997', 'morel1974'],
  },
  caustics: {
    text: {
      en: 'Caustics are the bright net of light on the sea bed. Each wave is a small lens: sunlight refracted through it converges in some places and spreads in others. For every point of the bed the shader follows three rays from the corners of a 0.75 m patch of the surface, refracts them by Snell’s law, and compares the area A_bed their landing points span with the patch’s own area A_surface. A patch squeezed to half its area receives twice the light. Where rays cross, the gain would be infinite, so it is capped at 8; Caustics intensity s then mixes it with the flat light, 1.',
      es: 'Las cáusticas son la red brillante de luz en el fondo. Cada ola es una pequeña lente: la luz del sol refractada converge en unos sitios y se dispersa en otros. Para cada punto del fondo el shader sigue tres rayos desde las esquinas de un trozo de superficie de 0,75 m, los refracta con la ley de Snell y compara el área A_bed que abarcan sus puntos de llegada con el área propia del trozo, A_surface. Un trozo comprimido a la mitad de su área recibe el doble de luz. Donde los rayos se cruzan la ganancia sería infinita, así que se limita a 8; la intensidad de las cáusticas s la mezcla con la luz plana, 1.',
    },
    math: m('<mtext>gain</mtext><mo>=</mo><mi>min</mi><mo>(</mo><mfrac><msub><mi>A</mi><mtext>surface</mtext></msub><msub><mi>A</mi><mtext>bed</mtext></msub></mfrac><mo>,</mo><mn>8</mn><mo>)</mo>') + m('<mi>E</mi><mo>=</mo><mi>max</mi><mo>(</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>+</mo><mi>s</mi><mo>(</mo><mtext>gain</mtext><mo>−</mo><mn>1</mn><mo>)</mo><mo>)</mo>'),
    choice: {
      en: 'The cap at 8 and an intensity above 1 are choices: a true caustic is unbounded on its fold lines, and intensity 2 or 3 exaggerates the contrast.',
      es: 'El límite de 8 y una intensidad mayor que 1 son elecciones: una cáustica real no tiene cota en sus pliegues, y una intensidad 2 o 3 exagera el contraste.',
    },
    question: {
      ask: {
        en: 'Set Caustics intensity to 0: will the bed go dark, keep its net, or turn evenly lit?',
        es: 'Pon la intensidad de las cáusticas en 0: ¿el fondo se oscurecerá, conservará su red o quedará iluminado por igual?',
      },
      answer: {
        en: 'Evenly lit: the shader mixes 1 and the gain by the intensity, so at 0 every point gets the sunlight a flat sea would send, still dimmed by the water above it. The bright net and the dim cells between it vanish together.',
        es: 'Iluminado por igual: el shader mezcla 1 y la ganancia según la intensidad, así que con 0 cada punto recibe la luz que enviaría un mar plano, atenuada aún por el agua de encima. La red brillante y las celdas tenues entre sus líneas desaparecen a la vez.',
      },
    },
    references: ['watt1990'],
  },
  'god-rays': {
    text: {
      en: 'God rays are shafts of sunlight made visible by the water. The shader marches N = 40 steps of length Δt along each line of sight, up to 60 m. At step i, at distance t_i and depth d_i, it reads S, the light the waves let through where that sunlight crossed the surface; dims it over its path down, d_i/μ with μ the cosine of the refracted sun’s zenith angle, and on to the eye, t_i, by extinction σε per channel; fades the shafts’ contrast over D = 30 m of depth; and scatters by σ and a phase p(θ), θ the angle from the sun’s direction. Each factor is exponential in t: each step multiplies by constants.',
      es: 'Los rayos de luz son haces de sol que el agua hace visibles. El shader avanza N = 40 pasos de longitud Δt por cada línea de visión, hasta 60 m. En el paso i, a distancia t_i y profundidad d_i, lee S, la luz que dejan pasar las olas donde ese sol cruzó la superficie; la atenúa bajando, d_i/μ con μ el coseno del ángulo cenital del sol refractado, y hasta el ojo, t_i, con la extinción σε de cada canal; desvanece el contraste de los haces en D = 30 m de profundidad; y dispersa según σ y una fase p(θ), θ el ángulo respecto del sol. Cada factor es exponencial en t: cada paso multiplica por constantes.',
    },
    math:
      m('<mi>L</mi><mo>=</mo><mi>σ</mi><mspace width="0.1em"/><mi>p</mi><mo>(</mo><mi>θ</mi><mo>)</mo><mspace width="0.1em"/><mi>Δ</mi><mi>t</mi><munderover><mo>∑</mo><mrow><mi>i</mi><mo>=</mo><mn>1</mn></mrow><mi>N</mi></munderover><mi>S</mi><mo>(</mo><msub><mi>s</mi><mi>i</mi></msub><mo>)</mo><mspace width="0.1em"/><msup><mi>e</mi><mrow><mo>−</mo><msub><mi>d</mi><mi>i</mi></msub><mo>/</mo><mi>D</mi></mrow></msup><mspace width="0.1em"/><msup><mi>e</mi><mrow><mo>−</mo><mi>σ</mi><mi>ε</mi><mo>(</mo><msub><mi>t</mi><mi>i</mi></msub><mo>+</mo><msub><mi>d</mi><mi>i</mi></msub><mo>/</mo><mi>μ</mi><mo>)</mo></mrow></msup>') +
      m('<mi>p</mi><mo>(</mo><mi>θ</mi><mo>)</mo><mo>=</mo><mn>0.3</mn><mo>+</mo><mn>3</mn><msup><mi>cos</mi><mn>4</mn></msup><mi>θ</mi>'),
    choice: {
      en: 'S is a stand-in, the ripples’ height band-passed and cubed, not refraction; the phase p(θ), the 30 m fade and the gain are artistic.',
      es: 'S es un sustituto, la altura de las ondas filtrada en banda y al cubo, no refracción; la fase p(θ), el desvanecimiento en 30 m y la ganancia son artísticos.',
    },
    question: {
      ask: {
        en: 'Raise Water fog density from this view’s 0.035 to 0.3 per metre: more water to scatter light, so brighter shafts, or fainter ones?',
        es: 'Sube la densidad de niebla de 0,035, la de esta vista, a 0,3 por metro: más agua que dispersa la luz, ¿haces más brillantes o más tenues?',
      },
      answer: {
        en: 'Fainter, shorter and bluer. Each metre scatters more (the factor σ), but the sunlight must first cross some 12 m of water to the camera’s depth and then reach the eye: at 0.3 the green keeps about 3 % over those 12 m, the blue about a fifth.',
        es: 'Más tenues, más cortos y más azules. Cada metro dispersa más (el factor σ), pero la luz del sol debe cruzar antes unos 12 m de agua hasta la profundidad de la cámara y luego llegar al ojo: con 0,3 el verde conserva cerca del 3 % en esos 12 m, el azul alrededor de una quinta parte.',
      },
    },
    references: ['popeFry1997', 'morel1974'],
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
      en: 'The three wave models side by side, on one camera and one noise seed. Left, the seed’s sines and its octaves of value noise (the report calls them Perlin); middle, 32 Gerstner trochoids drawn from the wind spectrum; right, Tessendorf’s FFT of the same spectrum. Only the middle and right models follow the 10 m/s wind: the seed’s waves read no wind at all. Each model draws only its strip of the screen. A divider at fraction f of the part of the view the panels leave free, from pixel column x₀ to x₁, stands on the column below. Drag the dividers, or move them with the arrow keys.',
      es: 'Los tres modelos de olas lado a lado, con una cámara y una semilla de ruido. A la izquierda, los senos del informe y sus octavas de ruido de valor (el informe lo llama Perlin); en el centro, 32 trocoides de Gerstner tomadas del espectro del viento; a la derecha, la FFT de Tessendorf del mismo espectro. Solo el centro y la derecha siguen el viento de 10 m/s: las olas del informe no leen el viento. Cada modelo dibuja solo su franja. Un divisor en la fracción f de la parte libre de la vista, de la columna de píxeles x₀ a x₁, queda en la columna de abajo. Arrastra los divisores o muévelos con las flechas.',
    },
    math: m('<msub><mi>x</mi><mtext>split</mtext></msub><mo>=</mo><mtext>round</mtext><mo>(</mo><msub><mi>x</mi><mn>0</mn></msub><mo>+</mo><mi>f</mi><mo>·</mo><mo>(</mo><msub><mi>x</mi><mn>1</mn></msub><mo>−</mo><msub><mi>x</mi><mn>0</mn></msub><mo>)</mo><mo>)</mo>'),
    question: {
      ask: {
        en: 'Before you touch anything: if you raise Wind speed from 10 to 20 m/s, which strips will change their waves, and which will not?',
        es: 'Antes de tocar nada: si subes la velocidad del viento de 10 a 20 m/s, ¿qué franjas cambian sus olas y cuáles no?',
      },
      answer: {
        en: 'The middle and right strips grow taller and longer: both are drawn from the wind’s spectrum, whose Hs grows as U². The left strip keeps its waves, since the seed’s sines and value noise read no wind; only its glint’s roughness, Cox and Munk’s σ² for the wind, changes.',
        es: 'Las franjas del centro y de la derecha crecen en altura y longitud: ambas salen del espectro del viento, cuya Hs crece como U². La franja izquierda conserva sus olas, porque los senos y el ruido de valor del informe no leen el viento; solo cambia la rugosidad de su destello, la σ² de Cox y Munk para ese viento.',
      },
    },
    choice: {
      en: 'The seed’s sines and value noise are an artistic model drawn from no spectrum; only the Gerstner and FFT strips come from the wind.',
      es: 'Los senos y el ruido de valor del informe son un modelo artístico sin espectro; solo Gerstner y la FFT salen del espectro del viento.',
    },
    references: ['gerstner1802', 'fournierReeves1986', 'tessendorf2001', 'piersonMoskowitz1964'],
  },
  'physics-panel': {
    text: {
      en: 'Does the sea obey physics? The panel measures it through its CPU twin. At one point it records the height over time: four times its standard deviation σ_η is the measured significant wave height Hs, and its spectrum’s peak ωp gives the peak period Tp. Beside them stands theory: 4√m₀, m₀ being the variance of the model’s spectrum, and Pierson and Moskowitz’s law at U₁₉.₅ = 1.026 U₁₀, the wind 19.5 m up. At 10 m/s theory gives Hs ≈ 2.25 m and Tp ≈ 7.5 s. On a patch, the panel also times each Fourier mode’s phase, ω, against √(g k tanh kh), g being gravity, k its wavenumber and h the depth.',
      es: '¿Obedece el mar a la física? El panel lo mide con su gemelo en CPU. Registra la altura en un punto: cuatro veces su desviación típica σ_η es la altura significativa medida Hs, y el pico ωp de su espectro da el periodo de pico Tp. Al lado, la teoría: 4√m₀, con m₀ la varianza del espectro del modelo, y la ley de Pierson y Moskowitz con U₁₉.₅ = 1,026 U₁₀, el viento a 19,5 m. A 10 m/s: Hs ≈ 2,25 m y Tp ≈ 7,5 s. En un parche cronometra la fase de cada modo de Fourier, ω, frente a √(g k tanh kh), con g la gravedad, k su número de onda y h la profundidad.',
    },
    math:
      m('<msub><mi>H</mi><mi>s</mi></msub><mo>=</mo><mn>4</mn><msub><mi>σ</mi><mi>η</mi></msub><mo>≈</mo><mn>4</mn><msqrt><msub><mi>m</mi><mn>0</mn></msub></msqrt><mo>≈</mo><mn>0.21</mn><mfrac><msubsup><mi>U</mi><mn>19.5</mn><mn>2</mn></msubsup><mi>g</mi></mfrac>') +
      m('<msub><mi>T</mi><mi>p</mi></msub><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi></mrow><msub><mi>ω</mi><mi>p</mi></msub></mfrac><mo>,</mo><mspace width="0.5em"/><msub><mi>ω</mi><mi>p</mi></msub><mo>=</mo><mn>0.877</mn><mfrac><mi>g</mi><msub><mi>U</mi><mn>19.5</mn></msub></mfrac><mo>,</mo><mspace width="0.5em"/><msub><mi>U</mi><mn>19.5</mn></msub><mo>=</mo><mn>1.026</mn><msub><mi>U</mi><mn>10</mn></msub>'),
    question: {
      ask: {
        en: 'At 10 m/s theory’s Hs is about 2.25 m. If you double Wind speed to 20 m/s, will Hs double, or grow by more? And the peak period?',
        es: 'A 10 m/s la Hs de la teoría ronda los 2,25 m. Si duplicas la velocidad del viento a 20 m/s, ¿se duplica Hs o crece más? ¿Y el periodo de pico?',
      },
      answer: {
        en: 'Hs grows about fourfold, to ≈ 9.0 m: Pierson and Moskowitz’s Hs, and 4√m₀ of the spectrum the sea is drawn from, go as U². The peak period doubles, from ≈ 7.5 s to ≈ 15 s, because ωp ∝ g/U. Move Wind speed and let the panel measure the new sea.',
        es: 'Hs crece unas cuatro veces, hasta ≈ 9,0 m: la Hs de Pierson y Moskowitz, y el 4√m₀ del espectro del que sale el mar, van como U². El periodo de pico se duplica, de ≈ 7,5 s a ≈ 15 s, porque ωp ∝ g/U. Mueve la velocidad del viento y deja que el panel mida el mar nuevo.',
      },
    },
    references: ['piersonMoskowitz1964', 'hasselmann1973', 'stewart2008', 'holthuijsen2007', 'welch1967'],
  },
  'kelvin-wake': {
    text: {
      en: 'A boat at U = 4 m/s on calm deep water: a Froude number U/√(gL) of 0.45 for its hull of length L = 8 m, g being gravity. Kelvin showed that a small disturbance moving straight at constant speed leaves its waves inside a wedge of half-angle α = arcsin(1/3) = 19.47°, whatever the speed. The two guide lines are drawn from that theory; the waves come from sources along the boat’s track, each spreading since it was left. The largest crests lie a little inside, about 18.3° at 14 wavelengths astern: the cusp is smoothed. The transverse waves behind the stern are λt = 2πU²/g ≈ 10.2 m long.',
      es: 'Un barco a U = 4 m/s en aguas profundas en calma: número de Froude U/√(gL) = 0,45 para su eslora L = 8 m, con g la gravedad. Kelvin demostró que una perturbación pequeña que avanza recta a velocidad constante deja sus olas dentro de una cuña de semiángulo α = arcsen(1/3) = 19,47°, sea cual sea la velocidad. Las líneas guía salen de esa teoría; las olas, de fuentes a lo largo de la derrota, cada una extendiéndose desde que quedó atrás. Las crestas mayores quedan algo dentro, a unos 18,3° a 14 longitudes de onda por popa: la cúspide se suaviza. Las olas transversales tras la popa miden λt = 2πU²/g ≈ 10,2 m.',
    },
    math:
      m('<mi>α</mi><mo>=</mo><mi>arcsin</mi><mfrac><mn>1</mn><mn>3</mn></mfrac><mo>=</mo><mn>19.47</mn><mo>°</mo>') +
      m('<msub><mi>λ</mi><mtext>t</mtext></msub><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi><msup><mi>U</mi><mn>2</mn></msup></mrow><mi>g</mi></mfrac><mo>≈</mo><mn>10.2</mn><mspace width="0.2em"/><mtext>m</mtext>') +
      m('<mi>Fr</mi><mo>=</mo><mfrac><mi>U</mi><msqrt><mi>g</mi><mi>L</mi></msqrt></mfrac><mo>=</mo><mn>0.45</mn>'),
    question: {
      ask: {
        en: 'If you raise Boat speed from 4 to 6 m/s, will the transverse waves get longer or shorter, and will the wedge open, close or keep its angle?',
        es: 'Si subes la velocidad del barco de 4 a 6 m/s, ¿las olas transversales se alargan o se acortan, y la cuña se abre, se cierra o conserva su ángulo?',
      },
      answer: {
        en: 'Longer: 2πU²/g grows from 10.2 m to 23 m. The wedge does not open: Kelvin’s edge stays at 19.47°, and at Fr = 0.68 the largest crests move further inside it, to about 16–17° in the code, as Darmon et al. found for fast hulls. Compare the crests with the guide lines.',
        es: 'Más largas: 2πU²/g pasa de 10,2 m a 23 m. La cuña no se abre: el borde de Kelvin sigue en 19,47°, y con Fr = 0,68 las crestas mayores se meten más dentro, a unos 16–17° en el código, como hallaron Darmon y colaboradores para cascos rápidos. Compara las crestas con las líneas guía.',
      },
    },
    choice: {
      en: 'The hull is a Gaussian pressure patch, each source taken in its far field (softened under the hull); waves older than 56–76 s fade out.',
      es: 'El casco es una mancha de presión gaussiana, cada fuente en su campo lejano (suavizada bajo el casco); las olas de más de 56–76 s se desvanecen.',
    },
    references: ['kelvin1887', 'lamb1932', 'lighthill1978', 'darmon2014', 'rabaudMoisy2013'],
  },
  'wake-turn': {
    text: {
      en: 'The same boat holding a turn of ω = 3° per second: at U = 4 m/s, a circle of radius U/ω ≈ 76 m. The wake is not a fixed wedge drawn behind the hull: its height η sums the waves left at every point xⱼ of the track τⱼ seconds ago, each over the Δτⱼ between samples. Each, G, is deep water’s answer to one push: at distance r the waves have wavenumber k = gτ²/(4r²), filtered by the hull’s footprint of radius σ = 2 m. So the wake bends with the curved track, and the guide, drawn straight back from the present heading, leaves it far behind the boat.',
      es: 'El mismo barco en un giro de ω = 3° por segundo: a U = 4 m/s, un círculo de radio U/ω ≈ 76 m. La estela no es una cuña fija tras el casco: su altura η suma las olas dejadas en cada punto xⱼ de la derrota hace τⱼ segundos, cada una por el Δτⱼ entre muestras. Cada una, G, responde como el agua profunda a un empujón: a distancia r las olas tienen número de onda k = gτ²/(4r²), filtrado por la huella del casco, de radio σ = 2 m. Así la estela se curva con la derrota, y la guía, trazada recta hacia atrás desde el rumbo actual, se separa de ella lejos del barco.',
    },
    math:
      m('<mi>η</mi><mo>(</mo><mi mathvariant="bold">x</mi><mo>)</mo><mo>=</mo><munder><mo>∑</mo><mi>j</mi></munder><mi>Δ</mi><msub><mi>τ</mi><mi>j</mi></msub><mspace width="0.1em"/><mi>G</mi><mo>(</mo><mo>|</mo><mi mathvariant="bold">x</mi><mo>−</mo><msub><mi mathvariant="bold">x</mi><mi>j</mi></msub><mo>|</mo><mo>,</mo><msub><mi>τ</mi><mi>j</mi></msub><mo>)</mo>') +
      m('<mi>G</mi><mo>(</mo><mi>r</mi><mo>,</mo><mi>τ</mi><mo>)</mo><mo>∝</mo><mfrac><msup><mi>τ</mi><mn>3</mn></msup><msup><mi>r</mi><mn>4</mn></msup></mfrac><msup><mi>e</mi><mrow><mo>−</mo><msup><mi>k</mi><mn>2</mn></msup><msup><mi>σ</mi><mn>2</mn></msup><mo>/</mo><mn>4</mn></mrow></msup><mi>sin</mi><mfrac><mrow><mi>g</mi><msup><mi>τ</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><mi>r</mi></mrow></mfrac><mo>,</mo><mspace width="0.5em"/><mi>k</mi><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>τ</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><msup><mi>r</mi><mn>2</mn></msup></mrow></mfrac>'),
    question: {
      ask: {
        en: 'Far behind the turning boat, will the wake lie along the straight guide lines or along the curved track?',
        es: 'Lejos por detrás del barco que gira, ¿la estela sigue las líneas guía rectas o la derrota curva?',
      },
      answer: {
        en: 'Along the track: every source sits where the hull really was, so the wake follows the 76 m circle, while the guide lines point straight back from the present heading and leave it. Set Boat turn rate to 0 and, once the old track has aged out, the wake closes on the guide again.',
        es: 'Sigue la derrota: cada fuente está donde de verdad estuvo el casco, así que la estela sigue el círculo de 76 m, mientras las líneas guía apuntan rectas hacia atrás desde el rumbo actual y se separan. Pon el giro del barco a 0 y, cuando la derrota vieja haya envejecido, la estela vuelve a la guía.',
      },
    },
    choice: {
      en: 'The track keeps 64 points, every 0.5 s near the boat, every 2 s further back; waves older than 56–76 s fade out: a budget, not physics.',
      es: 'La derrota guarda 64 puntos, cada 0,5 s cerca del barco y cada 2 s más atrás; las olas de más de 56–76 s se desvanecen: presupuesto, no física.',
    },
    references: ['lamb1932', 'lighthill1978', 'darmon2014'],
  },
  'waves-as-simulation': {
    text: {
      en: 'The spectral ocean underneath is a closed form in time: its height η sums waves of wave vector k, amplitude h̃₀(k) and frequency ω(k), known at any t, so it reaches the horizon and any moment for free, but nothing can disturb it. The rings added on top are a simulation: a height field hⁿ at step n, advanced every Δt = 1/60 s on a 128 m grid (Δx = 0.5 m) round the camera’s focus by a 13 × 13 kernel G that keeps ω² = gk within 5 % for waves 1.5 to 10 m long, with damping α. It answers stones and the boat near the camera; a jump in time replays at most 10 s.',
      es: 'El océano espectral de fondo es una fórmula cerrada del tiempo: su altura η suma olas de vector de onda k, amplitud h̃₀(k) y frecuencia ω(k), conocidas en todo t: llega gratis al horizonte y a cualquier instante, pero nada lo perturba. Los anillos sumados son una simulación: un campo de alturas hⁿ en el paso n, avanzado cada Δt = 1/60 s en una malla de 128 m (Δx = 0,5 m) en torno al foco con un núcleo G de 13 × 13 que mantiene ω² = gk al 5 % para olas de 1,5 a 10 m, y amortiguamiento α. Responde a piedras y al barco cerca de la cámara; un salto repite como mucho 10 s.',
    },
    math:
      m('<mi>η</mi><mo>(</mo><mi mathvariant="bold">x</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>=</mo><munder><mo>∑</mo><mi mathvariant="bold">k</mi></munder><mo>[</mo><msub><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn></msub><mo>(</mo><mi mathvariant="bold">k</mi><mo>)</mo><msup><mi>e</mi><mrow><mi>i</mi><mi>ω</mi><mi>t</mi></mrow></msup><mo>+</mo><msubsup><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn><mo>*</mo></msubsup><mo>(</mo><mo>−</mo><mi mathvariant="bold">k</mi><mo>)</mo><msup><mi>e</mi><mrow><mo>−</mo><mi>i</mi><mi>ω</mi><mi>t</mi></mrow></msup><mo>]</mo><msup><mi>e</mi><mrow><mi>i</mi><mi mathvariant="bold">k</mi><mo>·</mo><mi mathvariant="bold">x</mi></mrow></msup>') +
      m('<msup><mi>h</mi><mrow><mi>n</mi><mo>+</mo><mn>1</mn></mrow></msup><mo>=</mo><mfrac><mrow><mn>2</mn><msup><mi>h</mi><mi>n</mi></msup><mo>−</mo><mo>(</mo><mn>1</mn><mo>−</mo><mfrac><mrow><mi>α</mi><mi>Δ</mi><mi>t</mi></mrow><mn>2</mn></mfrac><mo>)</mo><msup><mi>h</mi><mrow><mi>n</mi><mo>−</mo><mn>1</mn></mrow></msup><mo>−</mo><mfrac><mrow><mi>g</mi><mi>Δ</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mi>Δ</mi><mi>x</mi></mrow></mfrac><mo>(</mo><mi>G</mi><mo>∗</mo><msup><mi>h</mi><mi>n</mi></msup><mo>)</mo></mrow><mrow><mn>1</mn><mo>+</mo><mfrac><mrow><mi>α</mi><mi>Δ</mi><mi>t</mi></mrow><mn>2</mn></mfrac></mrow></mfrac>'),
    question: {
      ask: {
        en: 'When the stone’s ring runs over a spectral wave, will that wave change shape, or pass on as if the ring were not there?',
        es: 'Cuando el anillo de la piedra pasa sobre una ola espectral, ¿cambia la forma de esa ola o sigue como si el anillo no estuviera?',
      },
      answer: {
        en: 'It passes on unchanged: the two are only added. The spectral sea is a closed form that nothing feeds back into, and the ring spreads as it would on calm water. Turn Interactive waves off: the ring vanishes and the spectral sea is exactly the same.',
        es: 'Sigue igual: los dos solo se suman. El mar espectral es una fórmula cerrada en la que nada influye, y el anillo se abre como lo haría en agua en calma. Apaga las olas interactivas: el anillo desaparece y el mar espectral es exactamente el mismo.',
      },
    },
    choice: {
      en: 'The kernel is fitted by least squares, not Tessendorf’s Bessel sum; the damping (a factor e in 100 s) and the border’s sponge are numerical.',
      es: 'El núcleo se ajusta por mínimos cuadrados, no es la suma de Bessel de Tessendorf; el amortiguamiento (factor e en 100 s) y la esponja del borde son numéricos.',
    },
    references: ['tessendorf2001', 'tessendorf2004'],
  },
  'iwave-stone': {
    text: {
      en: 'A stone dropped on a calm sea. Deep water is dispersive: a wave of wavenumber k has frequency ω = √(gk), g being gravity, so its speed depends on its length: the long waves the stone made run ahead and the short ones trail, and the ring spreads into a train of crests, closer together towards the middle. Cauchy and Poisson worked out where the crests stand: at distance r after time t the waves have k = gt²/(4r²), and the crests sit at rₙ, where the phase gt²/(4r) is a whole number n of turns. The yellow rings are those crests, drawn from theory; the water around them is the simulation.',
      es: 'Una piedra cae en un mar en calma. El agua profunda es dispersiva: una ola de número de onda k tiene frecuencia ω = √(gk), con g la gravedad, así que su velocidad depende de su longitud: las olas largas que levanta la piedra se adelantan y las cortas quedan atrás, y el anillo se abre en un tren de crestas, más juntas hacia el centro. Cauchy y Poisson calcularon dónde están las crestas: a distancia r tras un tiempo t las olas tienen k = gt²/(4r²), y las crestas están en rₙ, donde la fase gt²/(4r) es un número entero n de vueltas. Los anillos amarillos son esas crestas, dibujadas desde la teoría; el agua alrededor es la simulación.',
    },
    math:
      m('<mi>k</mi><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><msup><mi>r</mi><mn>2</mn></msup></mrow></mfrac>') +
      m('<msub><mi>r</mi><mi>n</mi></msub><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mn>8</mn><mi>π</mi><mi>n</mi></mrow></mfrac>'),
    question: {
      ask: {
        en: 'Ten seconds after the stone falls, will its crests be farther apart at the front of the train or near the stone?',
        es: 'Diez segundos después de caer la piedra, ¿sus crestas estarán más separadas en el frente del tren o cerca de la piedra?',
      },
      answer: {
        en: 'At the front. At t = 10 s the rings stand at 19.5, 13.0, 9.8 and 7.8 m: gaps of 6.5, 3.3 and 2.0 m, since rₙ = gt²/(8πn). The long waves lead, the short ones trail. Set Speed to 0.1 and watch the gaps open as t² grows.',
        es: 'En el frente. A t = 10 s los anillos están a 19,5, 13,0, 9,8 y 7,8 m: separaciones de 6,5, 3,3 y 2,0 m, porque rₙ = gt²/(8πn). Las olas largas van delante y las cortas detrás. Pon la velocidad a 0,1 y mira cómo se abren las separaciones al crecer t².',
      },
    },
    choice: {
      en: 'The stone is a Gaussian bump of water 2 m high released at rest, not a falling body; rings show only where the grid carries waves.',
      es: 'La piedra es un bulto gaussiano de agua de 2 m de alto soltado en reposo, no un cuerpo que cae; hay anillos solo donde la malla lleva olas.',
    },
    references: ['lamb1932', 'tessendorf2004'],
  },
  'iwave-compare': {
    text: {
      en: 'The same stone twice. On the left, deep water’s equation for the height h, g being gravity: iWave’s kernel stands for √(−∇²), so a wave of wavenumber k has frequency ω = √(gk): every wavelength has its own speed, and the ring spreads into a train. On the right, the plain wave equation, which many games use for interactive water: every wave long against the grid runs at the same speed, here c = 2.56 m/s, so the stone leaves a single ring that keeps its shape, like sound or light. A sponge along the middle keeps the two halves apart. Switch the equation to see either one alone.',
      es: 'La misma piedra dos veces. A la izquierda, la ecuación del agua profunda para la altura h, con g la gravedad: el núcleo de iWave hace de √(−∇²), así que una ola de número de onda k tiene frecuencia ω = √(gk): cada longitud corre a su velocidad y el anillo se abre en un tren. A la derecha, la ecuación de ondas simple, usada en muchos juegos para el agua interactiva: toda ola larga frente a la malla corre a la misma velocidad, aquí c = 2,56 m/s, y la piedra deja un único anillo que conserva su forma, como el sonido o la luz. Una esponja central separa las mitades. Cambia la ecuación para ver cada una sola.',
    },
    math:
      m('<mfrac><mrow><msup><mo>∂</mo><mn>2</mn></msup><mi>h</mi></mrow><mrow><mo>∂</mo><msup><mi>t</mi><mn>2</mn></msup></mrow></mfrac><mo>=</mo><mo>−</mo><mi>g</mi><msqrt><mo>−</mo><msup><mo>∇</mo><mn>2</mn></msup></msqrt><mi>h</mi><mspace width="1em"/><mo>⇒</mo><mspace width="1em"/><msup><mi>ω</mi><mn>2</mn></msup><mo>=</mo><mi>g</mi><mi>k</mi>') +
      m('<mfrac><mrow><msup><mo>∂</mo><mn>2</mn></msup><mi>h</mi></mrow><mrow><mo>∂</mo><msup><mi>t</mi><mn>2</mn></msup></mrow></mfrac><mo>=</mo><msup><mi>c</mi><mn>2</mn></msup><msup><mo>∇</mo><mn>2</mn></msup><mi>h</mi><mspace width="1em"/><mo>⇒</mo><mspace width="1em"/><mi>ω</mi><mo>=</mo><mi>c</mi><mi>k</mi><mo>,</mo><mspace width="0.5em"/><mi>c</mi><mo>=</mo><msqrt><mfrac><mi>g</mi><mrow><mn>1.5</mn><mspace width="0.1em"/><mtext>rad/m</mtext></mrow></mfrac></msqrt><mo>=</mo><mn>2.56</mn><mspace width="0.2em"/><mtext>m/s</mtext>'),
    question: {
      ask: {
        en: 'After a few seconds, which half will show one ring and which a train of rings, and on which side do the crests crowd together?',
        es: 'Tras unos segundos, ¿qué mitad mostrará un anillo y cuál un tren de anillos, y en qué lado se apiñan las crestas?',
      },
      answer: {
        en: 'The right half shows one ring, its front at c·t (25.6 m after 10 s). The left half shows a train whose crests crowd towards the stone, because there short waves are slower than long ones. Switch Interactive waves: equation to see each alone.',
        es: 'La mitad derecha muestra un anillo, con su frente en c·t (25,6 m a los 10 s). La izquierda muestra un tren cuyas crestas se apiñan hacia la piedra, porque allí las olas cortas van más despacio que las largas. Cambia la ecuación de las olas interactivas para ver cada una sola.',
      },
    },
    choice: {
      en: 'c = 2.56 m/s is chosen: deep water’s phase speed at 1.5 rad/m, mid-band; the sponge between the halves is a numerical wall.',
      es: 'c = 2,56 m/s es una elección: la velocidad de fase del agua profunda a 1,5 rad/m; la esponja entre las mitades es un muro numérico.',
    },
    references: ['tessendorf2004', 'lamb1932'],
  },
  'iwave-boat': {
    text: {
      en: 'The boat at U = 4 m/s in the interactive waves. Its waterline is a solid in the field, so waves reflect from the hull; as it moves, its bow pushes aside Q = U·V/L cubic metres of water a second, V being its displaced volume and L its length, and its stern lets as much back in: 3.2 m³/s here. Those two sources make the near-field waves, and the boat rides them. Within D = 16 m of the boat the field carries its waves; beyond D the analytic Kelvin wake takes over, blended over 8 m, so no wave is counted twice.',
      es: 'El barco a U = 4 m/s en las olas interactivas. Su línea de flotación es un sólido en el campo, así que las olas se reflejan en el casco; al avanzar, la proa aparta Q = U·V/L metros cúbicos de agua por segundo, con V su volumen desplazado y L su eslora, y la popa deja volver otros tantos: aquí 3,2 m³/s. Esas dos fuentes forman las olas del campo cercano, y el barco navega sobre ellas. Hasta D = 16 m del barco el campo lleva sus olas; más allá, la estela analítica de Kelvin toma el relevo, mezclada a lo largo de 8 m, para no contar ninguna ola dos veces.',
    },
    math:
      m('<mi>Q</mi><mo>=</mo><mfrac><mrow><mi>U</mi><mi>V</mi></mrow><mi>L</mi></mfrac><mo>=</mo><mn>3.2</mn><mspace width="0.2em"/><msup><mtext>m</mtext><mn>3</mn></msup><mtext>/s</mtext>') +
      m('<mi>D</mi><mo>=</mo><mi>max</mi><mo>(</mo><mn>2</mn><mi>L</mi><mo>,</mo><mfrac><mrow><mn>2</mn><mi>π</mi><msup><mi>U</mi><mn>2</mn></msup></mrow><mi>g</mi></mfrac><mo>)</mo><mo>=</mo><mn>16</mn><mspace width="0.2em"/><mtext>m</mtext>'),
    question: {
      ask: {
        en: 'Set Boat speed to −2 m/s, going astern: where will the raised water stand, at the bow or at the stern?',
        es: 'Pon la velocidad del barco a −2 m/s, marcha atrás: ¿dónde quedará el agua levantada, en la proa o en la popa?',
      },
      answer: {
        en: 'At the stern, which now leads: Q = U·V/L changes sign with U, so the stern pushes 1.6 m³/s aside and the bow leaves a hollow. Volume is still kept, the two sources cancelling.',
        es: 'En la popa, que ahora va delante: Q = U·V/L cambia de signo con U, así que la popa aparta 1,6 m³/s y la proa deja un hueco. El volumen se conserva, porque las dos fuentes se anulan.',
      },
    },
    choice: {
      en: 'The hull’s flow is a stand-in: a bow source and a stern sink of equal flux; the hand-over at D and its 8 m blend are choices.',
      es: 'El flujo del casco es un sustituto: fuente en proa y sumidero en popa de igual caudal; el relevo en D y su mezcla de 8 m son elecciones.',
    },
    references: ['tessendorf2004', 'kelvin1887', 'lighthill1978'],
  },
  horizon: {
    text: {
      en: 'Beyond the 4 km grid of chunks the sea continues to the horizon in square rings, each ring’s cells (side cᵢ) twice the size of the previous ring’s, so a triangle keeps about the same size on screen at any distance. A skirt of triangles runs out past the last ring. The waves fade out over the first two rings, where the vertices lie too far apart to sample them. Far off, the air’s haze lays the horizon’s colour over the sea: its extinction at sea level is β₀ = 3.912 / V for a visibility V (Koschmieder), thinning with height y on a scale H = 1.2 km, so the sea below an aircraft is only lightly veiled.',
      es: 'Más allá de la malla de parcelas de 4 km, el mar sigue hasta el horizonte en anillos cuadrados, cada uno con celdas (de lado cᵢ) del doble que las del anterior: un triángulo mantiene en pantalla un tamaño parecido a cualquier distancia. Una falda de triángulos sigue más allá del último anillo. Las olas se desvanecen en los dos primeros anillos, cuyos vértices están demasiado separados para muestrearlas. A lo lejos, la calima cubre el mar con el color del horizonte: su extinción a nivel del mar es β₀ = 3,912 / V para una visibilidad V (Koschmieder) y disminuye con la altura y en una escala H = 1,2 km: bajo un avión el mar apenas se vela.',
    },
    math:
      m('<msub><mi>c</mi><mrow><mi>i</mi><mo>+</mo><mn>1</mn></mrow></msub><mo>=</mo><mn>2</mn><msub><mi>c</mi><mi>i</mi></msub>') +
      m('<msub><mi>β</mi><mn>0</mn></msub><mo>=</mo><mfrac><mrow><mi>ln</mi><mspace width="0.17em"/><mn>50</mn></mrow><mi>V</mi></mfrac><mo>≈</mo><mfrac><mn>3.912</mn><mi>V</mi></mfrac><mo>,</mo><mspace width="0.5em"/><mi>β</mi><mo>(</mo><mi>y</mi><mo>)</mo><mo>=</mo><msub><mi>β</mi><mn>0</mn></msub><msup><mi>e</mi><mrow><mo>−</mo><mi>y</mi><mo>/</mo><mi>H</mi></mrow></msup>'),
    question: {
      ask: {
        en: 'If you lower Visibility from 20 to 5 km, will the sea’s edge against the sky move closer, or stay put while the haze thickens?',
        es: 'Si bajas la visibilidad de 20 a 5 km, ¿el borde del mar contra el cielo se acerca, o se queda en su sitio mientras la calima se espesa?',
      },
      answer: {
        en: 'It stays put: the sea is flat, so its edge lies on the eye’s horizontal whatever the air. The haze thickens fourfold (β₀ = 3.912/V), so the sea gives way to the horizon’s colour much nearer. Turn Colour chunks by band off to see it: the band colours are painted over after the haze.',
        es: 'Se queda en su sitio: el mar es plano, así que su borde está en la horizontal del ojo sea cual sea el aire. La calima se hace cuatro veces más densa (β₀ = 3,912/V), así que el mar cede al color del horizonte mucho más cerca. Apaga los colores por banda para verlo: se pintan después de la calima.',
      },
    },
    choice: {
      en: 'A flat sea, with no Earth curvature: from 120 m a real horizon stands about 39 km away, 0.35° below the horizontal; here it lies on the horizontal.',
      es: 'Un mar plano, sin la curvatura de la Tierra: desde 120 m el horizonte real está a unos 39 km, 0,35° bajo la horizontal; aquí está en la horizontal.',
    },
    references: ['losassoHoppe2004', 'koschmieder1924', 'brunetonNeyret2008'],
  },
  'airy-waves': {
    text: {
      en: 'Linear (Airy) theory keeps only first-order terms in a wave’s steepness a k: η = a cos(kx − ωt), with amplitude a, wavenumber k, angular frequency ω, time t. In deep water a particle at depth z ≤ 0 circles with radius a e^{kz}: half a wavelength down, e^{−π} ≈ 4 % of the surface’s. The mean energy per square metre is E = ½ ρ g a² (ρ water’s density, g gravity), half kinetic, half potential. Here Q = 0.2, the control’s least (at Q = 0 Gerstner’s waves are Airy’s): N = 4 waves from JONSWAP share equally the variance m₀ᴮ of the band they sample, 98.9 % of the spectrum’s m₀: a = √(2 m₀ᴮ/N).',
      es: 'La teoría lineal (de Airy) conserva el primer orden en la pendiente a k: η = a cos(kx − ωt) (amplitud a, número de onda k, frecuencia angular ω, tiempo t). En aguas profundas una partícula a profundidad z ≤ 0 gira con radio a e^{kz}: a media longitud de onda, e^{−π} ≈ 4 % del superficial. La energía media por m² es E = ½ ρ g a² (ρ densidad del agua, g gravedad), mitad cinética, mitad potencial. Aquí Q = 0,2, mínimo del control (con Q = 0, olas de Airy): N = 4 olas de JONSWAP se reparten por igual la varianza m₀ᴮ de su banda (98,9 % de la m₀ del espectro): a = √(2 m₀ᴮ/N).',
    },
    math: m('<mi>η</mi><mo>=</mo><mi>a</mi><mspace width="0.2em"/><mi>cos</mi><mo>(</mo><mi>k</mi><mi>x</mi><mo>−</mo><mi>ω</mi><mi>t</mi><mo>)</mo><mo>,</mo><mspace width="1em"/><mi>r</mi><mo>(</mo><mi>z</mi><mo>)</mo><mo>=</mo><mi>a</mi><mspace width="0.1em"/><msup><mi>e</mi><mrow><mi>k</mi><mi>z</mi></mrow></msup>')
      + m('<mi>E</mi><mo>=</mo><mfrac><mn>1</mn><mn>2</mn></mfrac><mi>ρ</mi><mi>g</mi><msup><mi>a</mi><mn>2</mn></msup><mo>,</mo><mspace width="1em"/><mi>a</mi><mo>=</mo><msqrt><mfrac><mrow><mn>2</mn><msubsup><mi>m</mi><mn>0</mn><mi>B</mi></msubsup></mrow><mi>N</mi></mfrac></msqrt>'),
    question: {
      ask: {
        en: 'Raise the number of Gerstner waves from 4 to 16, Q staying 0.2: will each wave be higher or lower, and will the sea as a whole carry more energy?',
        es: 'Sube el número de olas de Gerstner de 4 a 16, con Q en 0,2: ¿cada ola será más alta o más baja, y llevará el mar en conjunto más energía?',
      },
      answer: {
        en: 'Each wave drops from 0.28 m to 0.14 m: a = √(2 m₀ᴮ/N) halves when N grows fourfold, so each wave carries a quarter of the energy, about 100 J/m² instead of 400. The total, ρ g m₀ᴮ ≈ 1.6 kJ/m², stays: the sea looks less regular, not higher. Move the Gerstner waves control.',
        es: 'Cada ola baja de 0,28 m a 0,14 m: a = √(2 m₀ᴮ/N) se reduce a la mitad si N se cuadruplica, y cada ola lleva un cuarto de la energía: unos 100 J/m², no 400. El total, ρ g m₀ᴮ ≈ 1,6 kJ/m², no cambia: el mar parece menos regular, no más alto. Mueve el control Ondas de Gerstner.',
      },
    },
    choice: {
      en: 'Only the surface is drawn, not the orbits beneath it; giving every wave an equal share of the variance is a sampling choice, not physics.',
      es: 'Solo se dibuja la superficie, no las órbitas bajo ella; dar a cada ola una parte igual de la varianza es una elección de muestreo, no física.',
    },
    references: ['airy1845', 'lamb1932', 'deanDalrymple1991'],
  },
  'group-velocity': {
    text: {
      en: 'Crests travel at the phase speed c = ω/k; energy, and so a group of waves, at the group velocity c_g = dω/dk. In deep water ω = √(g k) gives c_g = c/2: crests are born at a group’s back, run through it and die at its front. At depth h, c_g = ½ c (1 + 2kh / sinh 2kh), rising to c in shallow water. A stone’s rings rest on c_g = c/2: waves of wavenumber k have run r = c_g t in a time t; at radius r stand k = g t²/(4 r²), long waves ahead. Kelvin’s wedge, arcsin(1/3) ≈ 19.47°, comes from the same ½.',
      es: 'Las crestas avanzan a la velocidad de fase c = ω/k; la energía y los grupos de olas, a la velocidad de grupo c_g = dω/dk. En aguas profundas ω = √(g k) da c_g = c/2: las crestas nacen en la cola del grupo, lo cruzan y mueren en su frente. A profundidad h, c_g = ½ c (1 + 2kh / senh 2kh), c en aguas someras. Los anillos de una piedra se deben a c_g = c/2: las olas de número de onda k han recorrido r = c_g t en un tiempo t; en el radio r, k = g t²/(4 r²), las largas delante. La cuña de Kelvin, arcsen(1/3) ≈ 19,47°, sale del mismo ½.',
    },
    math: m('<mi>c</mi><mo>=</mo><mfrac><mi>ω</mi><mi>k</mi></mfrac><mo>,</mo><mspace width="1em"/><msub><mi>c</mi><mi>g</mi></msub><mo>=</mo><mfrac><mrow><mi>d</mi><mi>ω</mi></mrow><mrow><mi>d</mi><mi>k</mi></mrow></mfrac><mo>=</mo><mfrac><mi>c</mi><mn>2</mn></mfrac><mrow><mo>(</mo><mn>1</mn><mo>+</mo><mfrac><mrow><mn>2</mn><mi>k</mi><mi>h</mi></mrow><mrow><mi>sinh</mi><mn>2</mn><mi>k</mi><mi>h</mi></mrow></mfrac><mo>)</mo></mrow>')
      + m('<mi>r</mi><mo>=</mo><msub><mi>c</mi><mi>g</mi></msub><mi>t</mi><mo>=</mo><mfrac><mn>1</mn><mn>2</mn></mfrac><msqrt><mfrac><mi>g</mi><mi>k</mi></mfrac></msqrt><mspace width="0.1em"/><mi>t</mi><mspace width="1em"/><mo>⇔</mo><mspace width="1em"/><mi>k</mi><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><msup><mi>r</mi><mn>2</mn></msup></mrow></mfrac>'),
    question: {
      ask: {
        en: 'Set Speed (time scale) to 0.25 and follow one crest of the rings: will it keep its place in the train of waves, move out through it, or fall back?',
        es: 'Pon la velocidad (escala de tiempo) en 0,25 y sigue una cresta de los anillos: ¿se quedará en su sitio dentro del tren de olas, lo atravesará hacia fuera o se quedará atrás?',
      },
      answer: {
        en: 'It moves out through the train, fading at its front as new crests appear at its back: a crest runs at c, the waves of its length as a group at c_g = c/2. The guide’s rings, r = g t²/(8πn), mark where the crests stand now. Set Speed to 0.25; reopen the lesson to drop the stone again.',
        es: 'Lo atraviesa hacia fuera y se apaga en su frente mientras nacen crestas en su cola: una cresta corre a c; las olas de su longitud, como grupo, a c_g = c/2. Los anillos de la guía, r = g t²/(8πn), marcan dónde están las crestas. Pon la velocidad en 0,25; reabre la lección para soltar de nuevo la piedra.',
      },
    },
    choice: {
      en: 'The rings are iWave’s: its grid gives ω² = g k only approximately, for waves a few metres long; the stone is a bump of water released at rest.',
      es: 'Los anillos son de iWave: su malla da ω² = g k solo aproximadamente, para olas de pocos metros; la piedra es un bulto de agua soltado en reposo.',
    },
    references: ['lamb1932', 'kelvin1887', 'lighthill1978', 'deanDalrymple1991'],
  },
  'spectra-compared': {
    text: {
      en: 'A wind spectrum S(ω) gives the variance of the sea’s height per unit angular frequency ω; its area m₀ gives the significant height Hs = 4√m₀. All three follow Phillips’ α g² ω⁻⁵ above the peak and differ below it. Tessendorf’s Phillips: α = 8.1·10⁻³, cut exp(−(g/(U ω))⁴), U the wind. Pierson–Moskowitz, a fully developed sea: the same α, cut exp(−β (ω₀/ω)⁴), β = 0.74, ω₀ = g/U19.5 (wind 19.5 m up). JONSWAP, a growing sea: α and peak set by the fetch (α ≈ 0.010 here), the peak multiplied by γ = 3.3. At 10 m/s: Phillips 1.8 m and a 72 m peak, Pierson–Moskowitz 2.2 m and 88 m, JONSWAP over 100 km 2.1 m and 61 m.',
      es: 'Un espectro de viento S(ω) da la varianza de la altura por unidad de frecuencia angular ω; su área m₀ da la altura significativa Hs = 4√m₀. Los tres siguen el α g² ω⁻⁵ de Phillips sobre el pico y difieren bajo él. Phillips de Tessendorf: α = 8,1·10⁻³, corte exp(−(g/(U ω))⁴), U el viento. Pierson–Moskowitz, mar plenamente desarrollado: el mismo α, corte exp(−β (ω₀/ω)⁴), β = 0,74, ω₀ = g/U19.5 (viento a 19,5 m). JONSWAP, mar joven: α y pico según el fetch (aquí α ≈ 0,010), pico multiplicado por γ = 3,3. A 10 m/s: Phillips 1,8 m y pico de 72 m, Pierson–Moskowitz 2,2 m y 88 m, JONSWAP con 100 km 2,1 m y 61 m.',
    },
    math: m('<msub><mi>S</mi><mi>P</mi></msub><mo>=</mo><mfrac><mrow><mi>α</mi><msup><mi>g</mi><mn>2</mn></msup></mrow><msup><mi>ω</mi><mn>5</mn></msup></mfrac><msup><mi>e</mi><mrow><mo>−</mo><msup><mrow><mo>(</mo><mi>g</mi><mo>/</mo><mo>(</mo><mi>U</mi><mi>ω</mi><mo>)</mo><mo>)</mo></mrow><mn>4</mn></msup></mrow></msup><mo>,</mo><mspace width="1em"/><msub><mi>S</mi><mi>PM</mi></msub><mo>=</mo><mfrac><mrow><mi>α</mi><msup><mi>g</mi><mn>2</mn></msup></mrow><msup><mi>ω</mi><mn>5</mn></msup></mfrac><msup><mi>e</mi><mrow><mo>−</mo><mi>β</mi><msup><mrow><mo>(</mo><msub><mi>ω</mi><mn>0</mn></msub><mo>/</mo><mi>ω</mi><mo>)</mo></mrow><mn>4</mn></msup></mrow></msup>')
      + m('<msub><mi>H</mi><mi>s</mi></msub><mo>=</mo><mn>4</mn><msqrt><msub><mi>m</mi><mn>0</mn></msub></msqrt><mo>,</mo><mspace width="1em"/><msub><mi>m</mi><mn>0</mn></msub><mo>=</mo><msubsup><mo>∫</mo><mn>0</mn><mi>∞</mi></msubsup><mi>S</mi><mo>(</mo><mi>ω</mi><mo>)</mo><mspace width="0.1em"/><mi>d</mi><mi>ω</mi>'),
    question: {
      ask: {
        en: 'Switch the spectrum from Phillips to Pierson–Moskowitz, wind still 10 m/s: will the waves grow higher and longer, or lower and shorter?',
        es: 'Cambia el espectro de Phillips a Pierson–Moskowitz, con el viento aún a 10 m/s: ¿las olas serán más altas y largas, o más bajas y cortas?',
      },
      answer: {
        en: 'Higher and longer: Hs from 1.8 m to 2.2 m, the peak wavelength from 72 m to 88 m. Pierson–Moskowitz’s cut, with β = 0.74 and the wind taken 19.5 m up (2.6 % faster), sits at a lower ω and lets more long waves in. Move the spectrum control.',
        es: 'Más altas y más largas: Hs de 1,8 m a 2,2 m, la longitud de onda del pico de 72 m a 88 m. El corte de Pierson–Moskowitz, con β = 0,74 y el viento tomado a 19,5 m (un 2,6 % más rápido), cae en una ω menor y deja pasar más olas largas. Mueve el control de espectro.',
      },
    },
    choice: {
      en: 'Phillips’ cut is Tessendorf’s choice for graphics, not a measured sea; the code fixes its free amplitude with Phillips’ α, as in Pierson–Moskowitz.',
      es: 'El corte de Phillips es una elección de Tessendorf para gráficos, no un mar medido; el código fija su amplitud libre con el α de Phillips, como en Pierson–Moskowitz.',
    },
    references: ['phillips1958', 'tessendorf2001', 'piersonMoskowitz1964', 'hasselmann1973'],
  },
  'fft-transform': {
    text: {
      en: 'The sea starts from random amplitudes: for each wavevector k of an N × N grid, h̃₀(k) = (ξr + i ξi) √(P(k)/2), ξr and ξi Gaussian numbers drawn from the seed, P(k) half the spectrum’s variance in that cell (the other half sits at −k). At time t (ω the angular frequency), h̃(k, t) = h̃₀(k) e^{iωt} + h̃₀*(−k) e^{−iωt}, so h̃(−k, t) = h̃*(k, t): the inverse transform is real. It runs log₂N stages of butterflies along x, then z: 7 for N = 128, in 4 GPU passes per axis (radices 2, 4, 4, 4). The result repeats: a tile. Three tiles summed, sizes in ratios 4.73 and 4.46, hide the repeat.',
      es: 'Primero, amplitudes aleatorias: para cada vector de onda k de una malla N × N, h̃₀(k) = (ξr + i ξi) √(P(k)/2), con ξr y ξi gaussianos de la semilla y P(k) la mitad de la varianza del espectro en esa celda (la otra está en −k). En el instante t (ω la frecuencia angular), h̃(k, t) = h̃₀(k) e^{iωt} + h̃₀*(−k) e^{−iωt}, y h̃(−k, t) = h̃*(k, t): la transformada inversa es real. Recorre log₂N etapas de mariposas en x y luego en z: 7 para N = 128, en 4 pasadas de GPU por eje (radios 2, 4, 4, 4). El resultado se repite: una tesela. Tres teselas sumadas, en razón 4,73 y 4,46, ocultan la repetición.',
    },
    math: m('<msub><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn></msub><mo>(</mo><mi mathvariant="bold">k</mi><mo>)</mo><mo>=</mo><mo>(</mo><msub><mi>ξ</mi><mi>r</mi></msub><mo>+</mo><mi>i</mi><msub><mi>ξ</mi><mi>i</mi></msub><mo>)</mo><msqrt><mfrac><mrow><mi>P</mi><mo>(</mo><mi mathvariant="bold">k</mi><mo>)</mo></mrow><mn>2</mn></mfrac></msqrt>')
      + m('<mover><mi>h</mi><mo>~</mo></mover><mo>(</mo><mi mathvariant="bold">k</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>=</mo><msub><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn></msub><mo>(</mo><mi mathvariant="bold">k</mi><mo>)</mo><msup><mi>e</mi><mrow><mi>i</mi><mi>ω</mi><mi>t</mi></mrow></msup><mo>+</mo><msubsup><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn><mo>*</mo></msubsup><mo>(</mo><mo>−</mo><mi mathvariant="bold">k</mi><mo>)</mo><msup><mi>e</mi><mrow><mo>−</mo><mi>i</mi><mi>ω</mi><mi>t</mi></mrow></msup>')
      + m('<mover><mi>h</mi><mo>~</mo></mover><mo>(</mo><mo>−</mo><mi mathvariant="bold">k</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>=</mo><msup><mover><mi>h</mi><mo>~</mo></mover><mo>*</mo></msup><mo>(</mo><mi mathvariant="bold">k</mi><mo>,</mo><mi>t</mi><mo>)</mo>'),
    question: {
      ask: {
        en: 'Change the noise seed from 1 to 2: will the sea’s significant height Hs change much, or only where the crests stand?',
        es: 'Cambia la semilla del ruido de 1 a 2: ¿cambiará mucho la altura significativa Hs del mar, o solo dónde están las crestas?',
      },
      answer: {
        en: 'Mostly where the crests stand. The seed draws the ξ; P(k) fixes each mode’s expected variance, so the drawn sea’s Hs = 4√(Σ|h̃|²) moves only from 2.15 m to 2.25 m. In the physics panel 4√m₀ stays at 2.25 m, the spectrum’s: no seed enters it. Move the noise seed control.',
        es: 'Sobre todo dónde están las crestas. La semilla sortea los ξ; P(k) fija la varianza esperada de cada modo, así que la Hs = 4√(Σ|h̃|²) del mar sorteado solo pasa de 2,15 m a 2,25 m. En el panel de física 4√m₀ sigue en 2,25 m, la del espectro, sin semilla. Mueve el control de semilla del ruido.',
      },
    },
    choice: {
      en: 'The tiles’ sizes, their ratios 4.73 and 4.46 and the three cascades are our choices to hide the repeat, not physics.',
      es: 'Los tamaños de las teselas, sus razones 4,73 y 4,46 y las tres cascadas son elecciones nuestras para ocultar la repetición, no física.',
    },
    references: ['tessendorf2001', 'cooleyTukey1965', 'govindaraju2008'],
  },
  'slope-filtering': {
    text: {
      en: 'A far pixel spans metres of sea. A wave shorter than two footprints w cannot be drawn by the normal: sampled once a pixel it aliases, and the far sea sparkles. So, after Bruneton, Neyret and Holzschuch (2010), each FFT cascade c adds its slopes to the normal scaled by s_c, the share of its band, λ_min to λ_max in ln k, whose waves exceed 2w: it shows s_c² of its mean-square slope σ_c². The rest of Cox and Munk’s σ²_CM becomes facets inside the pixel, of mean-square slope σ²ᵤ, never below the sun’s disc σ²_⊙, which the glint and the sky’s blur integrate over. σ²_CM is 0.055 at 10 m/s; the cascades’ σ_c² hold 0.019.',
      es: 'Un píxel lejano abarca metros de mar. Una ola más corta que dos huellas w no cabe en la normal: muestreada una vez por píxel produce aliasing, y el mar lejano chispea. Así, según Bruneton et al. (2010), cada cascada c de la FFT suma a la normal sus pendientes por s_c, la parte de su banda (λ_min a λ_max, en ln k) cuyas olas superan 2w: muestra s_c² de su pendiente cuadrática media σ_c². El resto de la σ²_CM de Cox y Munk son facetas del píxel, de pendiente cuadrática media σ²ᵤ, nunca menor que la del disco solar σ²_⊙, que el destello y el desenfoque del cielo integran. σ²_CM vale 0,055 a 10 m/s; las σ_c² suman 0,019.',
    },
    math: m('<msub><mi>s</mi><mi>c</mi></msub><mo>=</mo><mi>clamp</mi><mrow><mo>(</mo><mfrac><mrow><mi>ln</mi><mo>(</mo><msub><mi>λ</mi><mi>max</mi></msub><mo>/</mo><mn>2</mn><mi>w</mi><mo>)</mo></mrow><mrow><mi>ln</mi><mo>(</mo><msub><mi>λ</mi><mi>max</mi></msub><mo>/</mo><msub><mi>λ</mi><mi>min</mi></msub><mo>)</mo></mrow></mfrac><mo>,</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>)</mo></mrow>')
      + m('<msubsup><mi>σ</mi><mi>u</mi><mn>2</mn></msubsup><mo>=</mo><mi>max</mi><mrow><mo>(</mo><msubsup><mi>σ</mi><mo>⊙</mo><mn>2</mn></msubsup><mo>,</mo><mspace width="0.3em"/><msubsup><mi>σ</mi><mi>CM</mi><mn>2</mn></msubsup><mo>−</mo><munder><mo>∑</mo><mi>c</mi></munder><msubsup><mi>s</mi><mi>c</mi><mn>2</mn></msubsup><msubsup><mi>σ</mi><mi>c</mi><mn>2</mn></msubsup><mo>)</mo></mrow>'),
    question: {
      ask: {
        en: 'The low sun’s glitter runs far out towards the horizon. If you turn Roughness (Cox & Munk) off, will the far part of the path stay as wide?',
        es: 'El destello del sol bajo llega lejos, hacia el horizonte. Si apagas la rugosidad (Cox y Munk), ¿seguirá igual de ancha la parte lejana del camino?',
      },
      answer: {
        en: 'No: far out it thins to a narrow streak of sparse sparkles. There a pixel spans metres, so the shorter cascades’ s_c fall towards 0 and the normal keeps only the longest cascade’s gentle slopes, σ_c² = 0.004 of Cox and Munk’s 0.055; the roughness that stood for the rest is gone, leaving the sun’s disc. Move the Roughness control.',
        es: 'No: lejos se vuelve una franja estrecha de chispas sueltas. Allí un píxel abarca metros, las s_c de las cascadas cortas caen hacia 0 y la normal guarda solo las pendientes suaves de la más larga, σ_c² = 0,004 de los 0,055 de Cox y Munk; sin rugosidad queda el disco del sol. Mueve el control de rugosidad.',
      },
    },
    choice: {
      en: 'Counting a wave drawn from two footprints (Nyquist), sharing in ln k (a k⁻³ tail) and scaling a cascade’s slopes by it are approximations; Cox and Munk’s σ² is measured.',
      es: 'Dibujar una ola desde dos huellas (Nyquist), contar en ln k (cola k⁻³) y escalar así una cascada entera son aproximaciones; la σ² de Cox y Munk es medida.',
    },
    references: ['bruneton2010', 'coxMunk1954'],
  },
  'light-units': {
    text: {
      en: 'The shaders compute light as linear radiance L with no ceiling (high dynamic range), in the sky’s units: the sky cube’s colours lie near 0.3–0.8, and the sun gives E = 4 on a surface facing it, so the glint’s core is many times white. A screen stops at 1. Each channel becomes c = 2^EV L, EV the exposure control in stops, then goes through the tone curve f: unchanged below the knee k = 0.6, rolling off above it, so that 1 shows as 0.85, 2 as 0.99, and from about 2.4 an 8-bit screen shows white. Last, three.js encodes f as sRGB, V = 1.055 f^{1/2.4} − 0.055: the knee is code 203 of 255.',
      es: 'Los shaders calculan la luz como radiancia lineal L sin techo (alto rango dinámico), en unidades del cielo: sus colores rondan 0,3–0,8 y el sol da E = 4 sobre una superficie de frente, así que el núcleo del destello es muchas veces blanco. Una pantalla se detiene en 1. Cada canal pasa a c = 2^EV L, EV la exposición en pasos, y entra en la curva de tono f: igual bajo el codo k = 0,6, suavizada encima: 1 se ve como 0,85, 2 como 0,99, y desde unos 2,4 una pantalla de 8 bits da blanco. Al final three.js codifica f en sRGB, V = 1,055 f^{1/2,4} − 0,055: el codo es el código 203 de 255.',
    },
    math: m('<mi>c</mi><mo>=</mo><msup><mn>2</mn><mi>EV</mi></msup><mi>L</mi><mo>,</mo><mspace width="1em"/><mi>f</mi><mo>(</mo><mi>c</mi><mo>)</mo><mo>=</mo><mi>k</mi><mo>+</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo><mo>(</mo><mn>1</mn><mo>−</mo><msup><mi>e</mi><mrow><mo>−</mo><mo>(</mo><mi>c</mi><mo>−</mo><mi>k</mi><mo>)</mo><mo>/</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo></mrow></msup><mo>)</mo><mspace width="0.3em"/><mtext>if</mtext><mspace width="0.3em"/><mi>c</mi><mo>&gt;</mo><mi>k</mi><mo>,</mo><mspace width="0.3em"/><mtext>else</mtext><mspace width="0.3em"/><mi>c</mi>')
      + m('<mi>V</mi><mo>=</mo><mn>1.055</mn><mspace width="0.1em"/><msup><mi>f</mi><mrow><mn>1</mn><mo>/</mo><mn>2.4</mn></mrow></msup><mo>−</mo><mn>0.055</mn><mspace width="0.3em"/><mtext>if</mtext><mspace width="0.3em"/><mi>f</mi><mo>&gt;</mo><mn>0.0031308</mn><mo>,</mo><mspace width="0.3em"/><mtext>else</mtext><mspace width="0.3em"/><mn>12.92</mn><mi>f</mi>'),
    question: {
      ask: {
        en: 'Lower the exposure from 0 to −2 EV: will the glint’s white core shrink as much as the sea around it darkens?',
        es: 'Baja la exposición de 0 a −2 EV: ¿el núcleo blanco del destello se encogerá tanto como se oscurece el mar a su alrededor?',
      },
      answer: {
        en: 'No. All light is divided by 4: the water, below the knee, shows a quarter of its linear light. But white needed only c ≥ 2.4, so after the division it still shows wherever L ≥ 9.6, and the sun’s core lies far above that; only the glint’s rim fades. Move the exposure control.',
        es: 'No. Toda la luz se divide entre 4: el agua, bajo el codo, muestra un cuarto de su luz lineal. Pero el blanco solo pedía c ≥ 2,4, así que tras la división sigue donde L ≥ 9,6, y el núcleo del sol queda muy por encima; solo se apaga el borde del destello. Mueve el control de exposición.',
      },
    },
    choice: {
      en: 'The knee k = 0.6, its exponential shoulder and the sun’s E = 4 (the low end of a clear sky’s 4–9) are display choices; sRGB is the screens’ standard.',
      es: 'El codo k = 0,6, su hombro exponencial y la E = 4 del sol (mínimo de un cielo claro, 4–9) son elecciones; sRGB es el estándar de las pantallas.',
    },
    references: ['reinhard2002', 'iec1999'],
  },
  'water-colour': {
    text: {
      en: 'Deep clear water’s colour is light scattered back up before it is absorbed: just below the surface a share R = f b_b/(a + b_b) returns, f = 0.33, a pure water’s absorption (Pope and Fry), b_b = b/2 its molecules’ backscattering, b ∝ λ^−4.3 (Morel) at wavelength λ. Red is absorbed within metres (a = 0.34 m⁻¹), blue scattered: R = 0.0005, 0.013, 0.045 in red, green, blue: dark blue. A thin crest backlit by the sun glows: light crossing d = 1 m of it is scattered forward by plankton (b_p, chlorophyll 1 mg/m³) with Henyey and Greenstein’s phase function p(θ), g = 0.924, θ the angle from the sun’s ray: greener than the deep blue.',
      es: 'El color del agua profunda es luz devuelta antes de absorberse: bajo la superficie vuelve R = f b_b/(a + b_b), f = 0,33, a la absorción del agua pura (Pope y Fry), b_b = b/2 la retrodispersión molecular, b ∝ λ^−4,3 (Morel), λ la longitud de onda. El rojo se absorbe en metros (a = 0,34 m⁻¹), el azul se dispersa: R = 0,0005, 0,013, 0,045 en rojo, verde, azul: azul oscuro. Una cresta fina a contraluz brilla: la luz que cruza d = 1 m se dispersa hacia delante en el plancton (b_p, clorofila 1 mg/m³) con la fase p(θ) de Henyey y Greenstein, g = 0,924, θ el ángulo con el rayo del sol: más verde.',
    },
    math: m('<mi>R</mi><mo>=</mo><mfrac><mrow><mi>f</mi><msub><mi>b</mi><mi>b</mi></msub></mrow><mrow><mi>a</mi><mo>+</mo><msub><mi>b</mi><mi>b</mi></msub></mrow></mfrac><mo>,</mo><mspace width="1em"/><msub><mi>L</mi><mtext>glow</mtext></msub><mo>∝</mo><msub><mi>b</mi><mi>p</mi></msub><mi>d</mi><mspace width="0.1em"/><msup><mi>e</mi><mrow><mo>−</mo><mo>(</mo><mi>a</mi><mo>+</mo><msub><mi>b</mi><mi>p</mi></msub><mo>)</mo><mi>d</mi></mrow></msup><mi>p</mi><mo>(</mo><mi>θ</mi><mo>)</mo>')
      + m('<mi>p</mi><mo>(</mo><mi>θ</mi><mo>)</mo><mo>=</mo><mfrac><mrow><mn>1</mn><mo>−</mo><msup><mi>g</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><mi>π</mi><msup><mrow><mo>(</mo><mn>1</mn><mo>+</mo><msup><mi>g</mi><mn>2</mn></msup><mo>−</mo><mn>2</mn><mi>g</mi><mi>cos</mi><mi>θ</mi><mo>)</mo></mrow><mrow><mn>3</mn><mo>/</mo><mn>2</mn></mrow></msup></mrow></mfrac>'),
    question: {
      ask: {
        en: 'Turn the sun round behind you, sun azimuth from 20° to 200°: will the crests still glow green?',
        es: 'Gira el sol hasta tu espalda, azimut del sol de 20° a 200°: ¿seguirán brillando en verde las crestas?',
      },
      answer: {
        en: 'No. The glow is light scattered forward: p(θ) is 26.5 sr⁻¹ along the sun’s ray and under 0.005 sr⁻¹ at 90°, and the crests’ faces towards you are now sunlit, not backlit. The water’s own dark blue and the sky’s reflection remain. Move the sun azimuth control.',
        es: 'No. El brillo es luz dispersada hacia delante: p(θ) vale 26,5 sr⁻¹ en la dirección del rayo del sol y menos de 0,005 sr⁻¹ a 90°, y las caras de las crestas hacia ti quedan iluminadas de frente, no a contraluz. Quedan el azul oscuro del agua y el reflejo del cielo. Mueve el control de azimut del sol.',
      },
    },
    choice: {
      en: 'Chlorophyll 1 mg/m³, the 1 m crest path and how much of a pixel is crest (Atlas’s and Crest’s forms) are choices; the picked water colour is an artistic override.',
      es: 'La clorofila de 1 mg/m³, el camino de 1 m y cuánto del píxel es cresta (Atlas, Crest) son elecciones; el color del agua elegido a mano es artístico.',
    },
    references: ['popeFry1997', 'morel1974', 'morelPrieur1977', 'morel1988', 'henyeyGreenstein1941'],
  },
};
