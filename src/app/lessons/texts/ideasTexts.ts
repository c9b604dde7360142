import type { LessonText } from './lessonText';
import { m } from './mathml';

/** The cards of the ideas under everything: linear waves, spectra, filtering, light. */
export const ideasTexts: Record<string, LessonText> = {
  'airy-waves': {
    text: {
      en: 'Linear (Airy) theory keeps only first-order terms in a wave’s steepness a k: η = a cos(kx − ωt), with amplitude a, wavenumber k, angular frequency ω, time t. In deep water a particle at depth z ≤ 0 circles with radius a e^{kz}: half a wavelength down, e^{−π} ≈ 4 % of the surface’s. The mean energy per square metre is E = ½ ρ g a² (ρ water’s density, g gravity), half kinetic, half potential. Here Q = 0.2, the control’s least (at Q = 0 Gerstner’s waves are Airy’s): N = 4 waves from JONSWAP share equally the variance m₀ᴮ of the band they sample, 98.9 % of the spectrum’s m₀: a = √(2 m₀ᴮ/N).',
      es: 'La teoría lineal (de Airy) conserva el primer orden en la pendiente a k: η = a cos(kx − ωt) (amplitud a, número de onda k, frecuencia angular ω, tiempo t). En aguas profundas una partícula a profundidad z ≤ 0 gira con radio a e^{kz}: a media longitud de onda, e^{−π} ≈ 4 % del superficial. La energía media por m² es E = ½ ρ g a² (ρ densidad del agua, g gravedad), mitad cinética, mitad potencial. Aquí Q = 0,2, mínimo del control (con Q = 0, olas de Airy): N = 4 olas de JONSWAP se reparten por igual la varianza m₀ᴮ de su banda (98,9 % de la m₀ del espectro): a = √(2 m₀ᴮ/N).',
    },
    math:
      m(
        '<mi>η</mi><mo>=</mo><mi>a</mi><mspace width="0.2em"/><mi>cos</mi><mo>(</mo><mi>k</mi><mi>x</mi><mo>−</mo><mi>ω</mi><mi>t</mi><mo>)</mo><mo>,</mo><mspace width="1em"/><mi>r</mi><mo>(</mo><mi>z</mi><mo>)</mo><mo>=</mo><mi>a</mi><mspace width="0.1em"/><msup><mi>e</mi><mrow><mi>k</mi><mi>z</mi></mrow></msup>',
      ) +
      m(
        '<mi>E</mi><mo>=</mo><mfrac><mn>1</mn><mn>2</mn></mfrac><mi>ρ</mi><mi>g</mi><msup><mi>a</mi><mn>2</mn></msup><mo>,</mo><mspace width="1em"/><mi>a</mi><mo>=</mo><msqrt><mfrac><mrow><mn>2</mn><msubsup><mi>m</mi><mn>0</mn><mi>B</mi></msubsup></mrow><mi>N</mi></mfrac></msqrt>',
      ),
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
    math:
      m(
        '<mi>c</mi><mo>=</mo><mfrac><mi>ω</mi><mi>k</mi></mfrac><mo>,</mo><mspace width="1em"/><msub><mi>c</mi><mi>g</mi></msub><mo>=</mo><mfrac><mrow><mi>d</mi><mi>ω</mi></mrow><mrow><mi>d</mi><mi>k</mi></mrow></mfrac><mo>=</mo><mfrac><mi>c</mi><mn>2</mn></mfrac><mrow><mo>(</mo><mn>1</mn><mo>+</mo><mfrac><mrow><mn>2</mn><mi>k</mi><mi>h</mi></mrow><mrow><mi>sinh</mi><mn>2</mn><mi>k</mi><mi>h</mi></mrow></mfrac><mo>)</mo></mrow>',
      ) +
      m(
        '<mi>r</mi><mo>=</mo><msub><mi>c</mi><mi>g</mi></msub><mi>t</mi><mo>=</mo><mfrac><mn>1</mn><mn>2</mn></mfrac><msqrt><mfrac><mi>g</mi><mi>k</mi></mfrac></msqrt><mspace width="0.1em"/><mi>t</mi><mspace width="1em"/><mo>⇔</mo><mspace width="1em"/><mi>k</mi><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><msup><mi>r</mi><mn>2</mn></msup></mrow></mfrac>',
      ),
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
    math:
      m(
        '<msub><mi>S</mi><mi>P</mi></msub><mo>=</mo><mfrac><mrow><mi>α</mi><msup><mi>g</mi><mn>2</mn></msup></mrow><msup><mi>ω</mi><mn>5</mn></msup></mfrac><msup><mi>e</mi><mrow><mo>−</mo><msup><mrow><mo>(</mo><mi>g</mi><mo>/</mo><mo>(</mo><mi>U</mi><mi>ω</mi><mo>)</mo><mo>)</mo></mrow><mn>4</mn></msup></mrow></msup><mo>,</mo><mspace width="1em"/><msub><mi>S</mi><mi>PM</mi></msub><mo>=</mo><mfrac><mrow><mi>α</mi><msup><mi>g</mi><mn>2</mn></msup></mrow><msup><mi>ω</mi><mn>5</mn></msup></mfrac><msup><mi>e</mi><mrow><mo>−</mo><mi>β</mi><msup><mrow><mo>(</mo><msub><mi>ω</mi><mn>0</mn></msub><mo>/</mo><mi>ω</mi><mo>)</mo></mrow><mn>4</mn></msup></mrow></msup>',
      ) +
      m(
        '<msub><mi>H</mi><mi>s</mi></msub><mo>=</mo><mn>4</mn><msqrt><msub><mi>m</mi><mn>0</mn></msub></msqrt><mo>,</mo><mspace width="1em"/><msub><mi>m</mi><mn>0</mn></msub><mo>=</mo><msubsup><mo>∫</mo><mn>0</mn><mi>∞</mi></msubsup><mi>S</mi><mo>(</mo><mi>ω</mi><mo>)</mo><mspace width="0.1em"/><mi>d</mi><mi>ω</mi>',
      ),
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
    math:
      m(
        '<msub><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn></msub><mo>(</mo><mi mathvariant="bold">k</mi><mo>)</mo><mo>=</mo><mo>(</mo><msub><mi>ξ</mi><mi>r</mi></msub><mo>+</mo><mi>i</mi><msub><mi>ξ</mi><mi>i</mi></msub><mo>)</mo><msqrt><mfrac><mrow><mi>P</mi><mo>(</mo><mi mathvariant="bold">k</mi><mo>)</mo></mrow><mn>2</mn></mfrac></msqrt>',
      ) +
      m(
        '<mover><mi>h</mi><mo>~</mo></mover><mo>(</mo><mi mathvariant="bold">k</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>=</mo><msub><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn></msub><mo>(</mo><mi mathvariant="bold">k</mi><mo>)</mo><msup><mi>e</mi><mrow><mi>i</mi><mi>ω</mi><mi>t</mi></mrow></msup><mo>+</mo><msubsup><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn><mo>*</mo></msubsup><mo>(</mo><mo>−</mo><mi mathvariant="bold">k</mi><mo>)</mo><msup><mi>e</mi><mrow><mo>−</mo><mi>i</mi><mi>ω</mi><mi>t</mi></mrow></msup>',
      ) +
      m(
        '<mover><mi>h</mi><mo>~</mo></mover><mo>(</mo><mo>−</mo><mi mathvariant="bold">k</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>=</mo><msup><mover><mi>h</mi><mo>~</mo></mover><mo>*</mo></msup><mo>(</mo><mi mathvariant="bold">k</mi><mo>,</mo><mi>t</mi><mo>)</mo>',
      ),
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
    math:
      m(
        '<msub><mi>s</mi><mi>c</mi></msub><mo>=</mo><mi>clamp</mi><mrow><mo>(</mo><mfrac><mrow><mi>ln</mi><mo>(</mo><msub><mi>λ</mi><mi>max</mi></msub><mo>/</mo><mn>2</mn><mi>w</mi><mo>)</mo></mrow><mrow><mi>ln</mi><mo>(</mo><msub><mi>λ</mi><mi>max</mi></msub><mo>/</mo><msub><mi>λ</mi><mi>min</mi></msub><mo>)</mo></mrow></mfrac><mo>,</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>)</mo></mrow>',
      ) +
      m(
        '<msubsup><mi>σ</mi><mi>u</mi><mn>2</mn></msubsup><mo>=</mo><mi>max</mi><mrow><mo>(</mo><msubsup><mi>σ</mi><mo>⊙</mo><mn>2</mn></msubsup><mo>,</mo><mspace width="0.3em"/><msubsup><mi>σ</mi><mi>CM</mi><mn>2</mn></msubsup><mo>−</mo><munder><mo>∑</mo><mi>c</mi></munder><msubsup><mi>s</mi><mi>c</mi><mn>2</mn></msubsup><msubsup><mi>σ</mi><mi>c</mi><mn>2</mn></msubsup><mo>)</mo></mrow>',
      ),
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
    math:
      m(
        '<mi>c</mi><mo>=</mo><msup><mn>2</mn><mi>EV</mi></msup><mi>L</mi><mo>,</mo><mspace width="1em"/><mi>f</mi><mo>(</mo><mi>c</mi><mo>)</mo><mo>=</mo><mi>k</mi><mo>+</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo><mo>(</mo><mn>1</mn><mo>−</mo><msup><mi>e</mi><mrow><mo>−</mo><mo>(</mo><mi>c</mi><mo>−</mo><mi>k</mi><mo>)</mo><mo>/</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo></mrow></msup><mo>)</mo><mspace width="0.3em"/><mtext>if</mtext><mspace width="0.3em"/><mi>c</mi><mo>&gt;</mo><mi>k</mi><mo>,</mo><mspace width="0.3em"/><mtext>else</mtext><mspace width="0.3em"/><mi>c</mi>',
      ) +
      m(
        '<mi>V</mi><mo>=</mo><mn>1.055</mn><mspace width="0.1em"/><msup><mi>f</mi><mrow><mn>1</mn><mo>/</mo><mn>2.4</mn></mrow></msup><mo>−</mo><mn>0.055</mn><mspace width="0.3em"/><mtext>if</mtext><mspace width="0.3em"/><mi>f</mi><mo>&gt;</mo><mn>0.0031308</mn><mo>,</mo><mspace width="0.3em"/><mtext>else</mtext><mspace width="0.3em"/><mn>12.92</mn><mi>f</mi>',
      ),
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
    math:
      m(
        '<mi>R</mi><mo>=</mo><mfrac><mrow><mi>f</mi><msub><mi>b</mi><mi>b</mi></msub></mrow><mrow><mi>a</mi><mo>+</mo><msub><mi>b</mi><mi>b</mi></msub></mrow></mfrac><mo>,</mo><mspace width="1em"/><msub><mi>L</mi><mtext>glow</mtext></msub><mo>∝</mo><msub><mi>b</mi><mi>p</mi></msub><mi>d</mi><mspace width="0.1em"/><msup><mi>e</mi><mrow><mo>−</mo><mo>(</mo><mi>a</mi><mo>+</mo><msub><mi>b</mi><mi>p</mi></msub><mo>)</mo><mi>d</mi></mrow></msup><mi>p</mi><mo>(</mo><mi>θ</mi><mo>)</mo>',
      ) +
      m(
        '<mi>p</mi><mo>(</mo><mi>θ</mi><mo>)</mo><mo>=</mo><mfrac><mrow><mn>1</mn><mo>−</mo><msup><mi>g</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><mi>π</mi><msup><mrow><mo>(</mo><mn>1</mn><mo>+</mo><msup><mi>g</mi><mn>2</mn></msup><mo>−</mo><mn>2</mn><mi>g</mi><mi>cos</mi><mi>θ</mi><mo>)</mo></mrow><mrow><mn>3</mn><mo>/</mo><mn>2</mn></mrow></msup></mrow></mfrac>',
      ),
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
