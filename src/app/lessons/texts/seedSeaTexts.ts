import type { LessonText } from './lessonText';
import { m } from './mathml';

/** The cards of the seed report’s sea: the grid, the swell, the noise, the normals. */
export const seedSeaTexts: Record<string, LessonText> = {
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
    math:
      m(
        '<mi>P</mi><mo>=</mo><mo>(</mo><mi>x</mi><mo>,</mo><mi>M</mi><mo>(</mo><mi>x</mi><mo>,</mo><mi>z</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>,</mo><mi>z</mi><mo>)</mo>',
      ) + m('<mi>M</mi><mo>=</mo><mi>s</mi><mo>+</mo><mi>r</mi>'),
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
    math:
      m(
        '<mi>h</mi><mo>=</mo><mi>A</mi><mspace width="0.2em"/><mi>sin</mi><mo>(</mo><mi>k</mi><mi>x</mi><mo>+</mo><mi>ω</mi><mi>t</mi><mo>)</mo><mspace width="0.2em"/><mi>cos</mi><mo>(</mo><mi>k</mi><mi>z</mi><mo>+</mo><mn>0.7</mn><mi>ω</mi><mi>t</mi><mo>)</mo>',
      ) +
      m(
        '<mi>h</mi><mo>=</mo><mfrac><mi>A</mi><mn>2</mn></mfrac><mo>[</mo><mi>sin</mi><mo>(</mo><mi>k</mi><mo>(</mo><mi>x</mi><mo>+</mo><mi>z</mi><mo>)</mo><mo>+</mo><mn>1.7</mn><mi>ω</mi><mi>t</mi><mo>)</mo><mo>+</mo><mi>sin</mi><mo>(</mo><mi>k</mi><mo>(</mo><mi>x</mi><mo>−</mo><mi>z</mi><mo>)</mo><mo>+</mo><mn>0.3</mn><mi>ω</mi><mi>t</mi><mo>)</mo><mo>]</mo>',
      ) +
      m('<mi>ω</mi><mo>=</mo><msqrt><mi>g</mi><mi>k</mi></msqrt>'),
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
    math:
      m(
        '<mi>λ</mi><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi></mrow><mi>k</mi></mfrac><mo>≈</mo><mn>31</mn><mspace width="0.2em"/><mtext>m</mtext>',
      ) +
      m(
        '<mfrac><mi>H</mi><mi>λ</mi></mfrac><mo>=</mo><mfrac><mrow><mn>2</mn><mi>A</mi></mrow><mi>λ</mi></mfrac><mo>≈</mo><mn>0.25</mn><mo>&gt;</mo><mfrac><mn>1</mn><mn>7</mn></mfrac>',
      ),
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
    math: m(
      '<mi>n</mi><mo>(</mo><mi>i</mi><mo>,</mo><mi>j</mi><mo>)</mo><mo>=</mo><mfrac><mi>h</mi><msup><mn>2</mn><mn>31</mn></msup></mfrac><mo>−</mo><mn>1</mn><mo>∈</mo><mo>[</mo><mo>−</mo><mn>1</mn><mo>,</mo><mn>1</mn><mo>)</mo>',
    ),
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
    math:
      m(
        '<mi>s</mi><mo>=</mo><mfrac><mi>n</mi><mn>4</mn></mfrac><mo>+</mo><mfrac><mi>e</mi><mn>8</mn></mfrac><mo>+</mo><mfrac><mi>c</mi><mn>16</mn></mfrac>',
      ) +
      m(
        '<msub><mi>σ</mi><mi>s</mi></msub><mo>=</mo><msqrt><mfrac><mn>1</mn><mn>16</mn></mfrac><mo>+</mo><mfrac><mn>4</mn><mn>64</mn></mfrac><mo>+</mo><mfrac><mn>4</mn><mn>256</mn></mfrac></msqrt><mspace width="0.2em"/><msub><mi>σ</mi><mi>n</mi></msub><mo>=</mo><mfrac><mn>3</mn><mn>8</mn></mfrac><msub><mi>σ</mi><mi>n</mi></msub>',
      ),
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
    math:
      m(
        '<mi>N</mi><mo>=</mo><mfrac><mrow><munderover><mo>∑</mo><mrow><mi>o</mi><mo>=</mo><mn>0</mn></mrow><mn>4</mn></munderover><msup><mi>p</mi><mi>o</mi></msup><mspace width="0.2em"/><msub><mi>n</mi><mi>o</mi></msub></mrow><mrow><munderover><mo>∑</mo><mrow><mi>o</mi><mo>=</mo><mn>0</mn></mrow><mn>4</mn></munderover><msup><mi>p</mi><mi>o</mi></msup></mrow></mfrac>',
      ) +
      m(
        '<msub><mi>H</mi><mn>0</mn></msub><mo>=</mo><mfrac><mrow><mi>N</mi><mo>−</mo><mover><mi>N</mi><mo>¯</mo></mover></mrow><mrow><mi>max</mi><mo>|</mo><mi>N</mi><mo>−</mo><mover><mi>N</mi><mo>¯</mo></mover><mo>|</mo></mrow></mfrac>',
      ),
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
    math:
      m(
        '<mi>r</mi><mo>=</mo><mi>S</mi><mspace width="0.2em"/><mo>[</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>b</mi><mo>)</mo><msub><mi>H</mi><mn>0</mn></msub><mo>(</mo><mi>p</mi><mo>+</mo><msub><mi>v</mi><mn>0</mn></msub><mi>t</mi><mo>)</mo><mo>+</mo><mi>b</mi><msub><mi>H</mi><mn>1</mn></msub><mo>(</mo><mi>p</mi><mo>+</mo><msub><mi>v</mi><mn>1</mn></msub><mi>t</mi><mo>)</mo><mo>]</mo>',
      ) +
      m(
        '<mi>b</mi><mo>=</mo><mfrac><mrow><mn>1</mn><mo>−</mo><mi>cos</mi><mo>(</mo><mi>β</mi><mi>t</mi><mo>)</mo></mrow><mn>2</mn></mfrac>',
      ),
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
    math:
      m('<mi>N</mi><mo>=</mo><mo>(</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>,</mo><mn>0</mn><mo>)</mo>') +
      m(
        '<mtext>colour</mtext><mo>=</mo><mfrac><mrow><mi>N</mi><mo>+</mo><mn>1</mn></mrow><mn>2</mn></mfrac><mo>=</mo><mo>(</mo><mn>0.5</mn><mo>,</mo><mn>1</mn><mo>,</mo><mn>0.5</mn><mo>)</mo>',
      ),
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
    math:
      m(
        '<mi>N</mi><mo>∝</mo><mo>(</mo><msub><mi>V</mi><mn>3</mn></msub><mo>−</mo><msub><mi>V</mi><mn>1</mn></msub><mo>)</mo><mo>×</mo><mo>(</mo><msub><mi>V</mi><mn>2</mn></msub><mo>−</mo><msub><mi>V</mi><mn>1</mn></msub><mo>)</mo>',
      ) +
      m(
        '<mi>N</mi><mo>∝</mo><mo>(</mo><mo>−</mo><mi>Δ</mi><mo>(</mo><msub><mi>h</mi><mn>2</mn></msub><mo>−</mo><msub><mi>h</mi><mn>1</mn></msub><mo>)</mo><mo>,</mo><msup><mi>Δ</mi><mn>2</mn></msup><mo>,</mo><mo>−</mo><mi>Δ</mi><mo>(</mo><msub><mi>h</mi><mn>3</mn></msub><mo>−</mo><msub><mi>h</mi><mn>1</mn></msub><mo>)</mo><mo>)</mo>',
      ),
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
};
