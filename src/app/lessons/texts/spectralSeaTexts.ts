import type { LessonText } from './lessonText';
import { m } from './mathml';

/** The cards of LOD and culling, the wind’s spectra, the FFT and Gerstner. */
export const spectralSeaTexts: Record<string, LessonText> = {
  'lod-bands': {
    text: {
      en: 'Level of detail, the seed’s optimisation: the sea is cut into square chunks 48 m wide, and each is drawn with fewer vertices the farther its nearest point lies from the camera, height included. Band b begins at distance d_b from the camera and keeps every s_b-th vertex: band 0, nearer than L, every vertex (2 m apart); band 1, from L, every 2nd; band 2, from 2L, every 3rd; then every 6th, 12th and 24th from 4L, 8L and 16L. The colours name the bands: red, orange, yellow, green, cyan, violet. This camera is 260 m up and L = 100 m.',
      es: 'Nivel de detalle, optimización del informe: el mar se divide en parcelas cuadradas de 48 m de lado, y cada una se dibuja con menos vértices cuanto más lejos de la cámara está su punto más cercano, altura incluida. La banda b empieza a la distancia d_b de la cámara y conserva uno de cada s_b vértices: la banda 0, a menos de L, todos (a 2 m); la banda 1, desde L, uno de cada dos; la banda 2, desde 2L, uno de cada tres; luego uno de cada 6, 12 y 24 desde 4L, 8L y 16L. Colores de las bandas: rojo, naranja, amarillo, verde, cian, violeta. Cámara a 260 m de altura, L = 100 m.',
    },
    math:
      m(
        '<msub><mi>d</mi><mn>0</mn></msub><mo>=</mo><mn>0</mn><mo>,</mo><mspace width="0.4em"/><msub><mi>d</mi><mi>b</mi></msub><mo>=</mo><mi>L</mi><mspace width="0.2em"/><msup><mn>2</mn><mrow><mi>b</mi><mo>−</mo><mn>1</mn></mrow></msup><mspace width="0.4em"/><mo>(</mo><mi>b</mi><mo>≥</mo><mn>1</mn><mo>)</mo>',
      ) +
      m(
        '<msub><mi>s</mi><mi>b</mi></msub><mo>=</mo><mn>1</mn><mo>,</mo><mn>2</mn><mo>,</mo><mn>3</mn><mo>,</mo><mn>6</mn><mo>,</mo><mn>12</mn><mo>,</mo><mn>24</mn>',
      ),
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
    math: m(
      '<msup><mi>k</mi><mo>′</mo></msup><mo>=</mo><mi>k</mi><mo>+</mo><mi>f</mi><mo>(</mo><msub><mi>k</mi><mi>c</mi></msub><mo>−</mo><mi>k</mi><mo>)</mo><mo>,</mo><mspace width="0.4em"/><mi>f</mi><mo>=</mo><mi>clamp</mi><mrow><mo>(</mo><mfrac><mrow><mi>d</mi><mo>−</mo><msub><mi>d</mi><mi>s</mi></msub></mrow><mi>w</mi></mfrac><mo>,</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>)</mo></mrow>',
    ),
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
    math:
      m(
        '<mtext>skip</mtext><mo>⇐</mo><mo>∃</mo><mi>π</mi><mo>:</mo><mspace width="0.2em"/><mi>n</mi><mo>·</mo><msup><mi>p</mi><mo>+</mo></msup><mo>+</mo><mi>d</mi><mo>&lt;</mo><mn>0</mn>',
      ) +
      m(
        '<mtext>inside</mtext><mo>⇔</mo><mo>∀</mo><mi>π</mi><mo>:</mo><mspace width="0.2em"/><mi>n</mi><mo>·</mo><msup><mi>p</mi><mo>−</mo></msup><mo>+</mo><mi>d</mi><mo>≥</mo><mn>0</mn>',
      ),
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
    math: m(
      '<mi>S</mi><mo>(</mo><mi>ω</mi><mo>)</mo><mo>=</mo><mfrac><mrow><mi>α</mi><msup><mi>g</mi><mn>2</mn></msup></mrow><msup><mi>ω</mi><mn>5</mn></msup></mfrac><mi>exp</mi><mrow><mo>(</mo><mo>−</mo><mi>β</mi><msup><mrow><mo>(</mo><mfrac><msub><mi>ω</mi><mn>0</mn></msub><mi>ω</mi></mfrac><mo>)</mo></mrow><mn>4</mn></msup><mo>)</mo></mrow><mo>,</mo><mspace width="0.4em"/><msub><mi>ω</mi><mn>0</mn></msub><mo>=</mo><mfrac><mi>g</mi><msub><mi>U</mi><mn>19.5</mn></msub></mfrac>',
    ),
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
    math: m(
      '<mi>S</mi><mo>(</mo><mi>ω</mi><mo>)</mo><mo>=</mo><mfrac><mrow><mi>α</mi><msup><mi>g</mi><mn>2</mn></msup></mrow><msup><mi>ω</mi><mn>5</mn></msup></mfrac><mi>exp</mi><mrow><mo>(</mo><mo>−</mo><mfrac><mn>5</mn><mn>4</mn></mfrac><msup><mrow><mo>(</mo><mfrac><msub><mi>ω</mi><mi>p</mi></msub><mi>ω</mi></mfrac><mo>)</mo></mrow><mn>4</mn></msup><mo>)</mo></mrow><msup><mi>γ</mi><mi>r</mi></msup><mo>,</mo><mspace width="0.4em"/><mi>r</mi><mo>=</mo><mi>exp</mi><mrow><mo>(</mo><mo>−</mo><mfrac><msup><mrow><mo>(</mo><mi>ω</mi><mo>−</mo><msub><mi>ω</mi><mi>p</mi></msub><mo>)</mo></mrow><mn>2</mn></msup><mrow><mn>2</mn><msup><mi>σ</mi><mn>2</mn></msup><msubsup><mi>ω</mi><mi>p</mi><mn>2</mn></msubsup></mrow></mfrac><mo>)</mo></mrow>',
    ),
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
    math:
      m(
        '<mi>det</mi><mi>J</mi><mo>=</mo><mo>(</mo><mn>1</mn><mo>+</mo><msub><mi>J</mi><mrow><mi>x</mi><mi>x</mi></mrow></msub><mo>)</mo><mo>(</mo><mn>1</mn><mo>+</mo><msub><mi>J</mi><mrow><mi>z</mi><mi>z</mi></mrow></msub><mo>)</mo><mo>−</mo><msubsup><mi>J</mi><mrow><mi>x</mi><mi>z</mi></mrow><mn>2</mn></msubsup>',
      ) +
      m(
        '<msub><mi>λ</mi><mtext>min</mtext></msub><mo>=</mo><mn>1</mn><mo>+</mo><mfrac><mrow><msub><mi>J</mi><mrow><mi>x</mi><mi>x</mi></mrow></msub><mo>+</mo><msub><mi>J</mi><mrow><mi>z</mi><mi>z</mi></mrow></msub></mrow><mn>2</mn></mfrac><mo>−</mo><msqrt><msup><mrow><mo>(</mo><mfrac><mrow><msub><mi>J</mi><mrow><mi>x</mi><mi>x</mi></mrow></msub><mo>−</mo><msub><mi>J</mi><mrow><mi>z</mi><mi>z</mi></mrow></msub></mrow><mn>2</mn></mfrac><mo>)</mo></mrow><mn>2</mn></msup><mo>+</mo><msubsup><mi>J</mi><mrow><mi>x</mi><mi>z</mi></mrow><mn>2</mn></msubsup></msqrt>',
      ) +
      m(
        '<mi>F</mi><mo>(</mo><mi>t</mi><mo>)</mo><mo>=</mo><msub><mi>F</mi><mn>0</mn></msub><mspace width="0.1em"/><msup><mi>e</mi><mrow><mo>−</mo><mi>t</mi><mo>/</mo><mi>τ</mi></mrow></msup>',
      ),
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
    math:
      m(
        '<mo>∇</mo><mi>h</mi><mo>=</mo><munder><mo>∑</mo><mi mathvariant="bold">k</mi></munder><mi>i</mi><mi mathvariant="bold">k</mi><mspace width="0.2em"/><mover><mi>h</mi><mo>~</mo></mover><mo>(</mo><mi mathvariant="bold">k</mi><mo>,</mo><mi>t</mi><mo>)</mo><msup><mi>e</mi><mrow><mi>i</mi><mi mathvariant="bold">k</mi><mo>·</mo><mi mathvariant="bold">x</mi></mrow></msup>',
      ) +
      m(
        '<mi>P</mi><mo>=</mo><mo>(</mo><mi>x</mi><mo>+</mo><msub><mi>D</mi><mi>x</mi></msub><mo>,</mo><mi>h</mi><mo>,</mo><mi>z</mi><mo>+</mo><msub><mi>D</mi><mi>z</mi></msub><mo>)</mo><mo>,</mo><mspace width="0.4em"/><mi>N</mi><mo>∝</mo><mfrac><mrow><mo>∂</mo><mi>P</mi></mrow><mrow><mo>∂</mo><mi>z</mi></mrow></mfrac><mo>×</mo><mfrac><mrow><mo>∂</mo><mi>P</mi></mrow><mrow><mo>∂</mo><mi>x</mi></mrow></mfrac>',
      ),
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
    math: m(
      '<mi>x</mi><mo>=</mo><msub><mi>x</mi><mn>0</mn></msub><mo>−</mo><munder><mo>∑</mo><mi>i</mi></munder><msub><mi>Q</mi><mi>i</mi></msub><msub><mi>A</mi><mi>i</mi></msub><msub><mover><mi>k</mi><mo>^</mo></mover><mi>i</mi></msub><mi>sin</mi><msub><mi>θ</mi><mi>i</mi></msub><mo>,</mo><mspace width="0.4em"/><mi>y</mi><mo>=</mo><munder><mo>∑</mo><mi>i</mi></munder><msub><mi>A</mi><mi>i</mi></msub><mi>cos</mi><msub><mi>θ</mi><mi>i</mi></msub>',
    ),
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
    math: m(
      '<munder><mo>∑</mo><mi>i</mi></munder><msub><mi>Q</mi><mi>i</mi></msub><msub><mi>k</mi><mi>i</mi></msub><msub><mi>A</mi><mi>i</mi></msub><mo>≤</mo><mn>1</mn><mo>,</mo><mspace width="0.4em"/><msub><mi>Q</mi><mi>i</mi></msub><mo>=</mo><mi>Q</mi><mspace width="0.1em"/><mi>min</mi><mrow><mo>(</mo><mn>1</mn><mo>,</mo><mfrac><mn>1</mn><mrow><msub><mo>∑</mo><mi>j</mi></msub><msub><mi>k</mi><mi>j</mi></msub><msub><mi>A</mi><mi>j</mi></msub></mrow></mfrac><mo>)</mo></mrow>',
    ),
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
};
