import type { LessonText } from './lessonText';
import { m } from './mathml';

/** The coast's cards: waves that feel the bottom, by linear wave theory (src/sim/coast/). */
export const coastTexts: Record<string, LessonText> = {
  'coast-dispersion': {
    text: {
      en: 'On the beach a swell of peak period 10 s runs in from 60 m of water, where a 10 s wave is L = 154 m long. Its period T stays the same all the way in: as many crests arrive each second as leave. So ω = 2π/T is fixed, and the depth h picks the wavenumber k through ω² = g k tanh(k h), g being gravity. As h falls, k grows: the crests stand 92 m apart at 10 m of water and 44 m apart at 2 m. Their phase speed c = ω/k falls with them towards √(g h): at 2 m, c = 4.37 m/s and √(g h) = 4.43 m/s.',
      es: 'En la playa un oleaje de periodo de pico 10 s llega desde 60 m de agua, donde una ola de 10 s mide L = 154 m. Su periodo T no cambia en el camino: cada segundo llegan tantas crestas como salen. Así ω = 2π/T queda fija, y la profundidad h elige el número de onda k mediante ω² = g k tanh(k h), con g la gravedad. Al bajar h, k crece: las crestas distan 92 m a 10 m de profundidad y 44 m a 2 m. Su velocidad de fase c = ω/k baja con ellas hacia √(g h): a 2 m, c = 4,37 m/s y √(g h) = 4,43 m/s.',
    },
    math:
      m(
        '<msup><mi>ω</mi><mn>2</mn></msup><mo>=</mo><mi>g</mi><mi>k</mi><mi>tanh</mi><mo>(</mo><mi>k</mi><mi>h</mi><mo>)</mo><mo>,</mo><mspace width="0.5em"/><mi>ω</mi><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi></mrow><mi>T</mi></mfrac><mo>,</mo><mspace width="0.5em"/><mi>L</mi><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi></mrow><mi>k</mi></mfrac>',
      ) +
      m(
        '<mi>c</mi><mo>=</mo><mfrac><mi>ω</mi><mi>k</mi></mfrac><mo>=</mo><msqrt><mfrac><mi>g</mi><mi>k</mi></mfrac><mi>tanh</mi><mo>(</mo><mi>k</mi><mi>h</mi><mo>)</mo></msqrt><mspace width="0.3em"/><mover><mo>→</mo><mrow><mi>k</mi><mi>h</mi><mo>≪</mo><mn>1</mn></mrow></mover><mspace width="0.3em"/><msqrt><mi>g</mi><mi>h</mi></msqrt>',
      ),
    question: {
      ask: {
        en: 'If you lengthen Swell period from 10 to 15 s, will the crests at 2 m of water stand much further apart, or hardly move?',
        es: 'Si alargas el periodo del oleaje de 10 a 15 s, ¿las crestas a 2 m de profundidad se separan mucho o casi nada?',
      },
      answer: {
        en: 'Much further apart, in proportion to the period: shallow water is hardly dispersive, every period runs at about √(g h), so L ≈ T √(g h), and at 2 m L grows from 44 m to 66 m. Move Swell period and watch the crests near the sand spread out.',
        es: 'Se separan mucho, en proporción al periodo: el agua somera apenas es dispersiva, todo periodo corre a casi √(g h), así que L ≈ T √(g h), y a 2 m L pasa de 44 m a 66 m. Mueve el periodo del oleaje y mira cómo se separan las crestas junto a la arena.',
      },
    },
    choice: {
      en: 'A long-crested swell: one direction, and its JONSWAP spectrum sampled at four periods, 11.2, 9.9, 8.8 and 6.1 s, each shortened by the depth on its own; below 0.1 m of water k is frozen, where the waves have long broken.',
      es: 'Un oleaje de crestas largas: una sola dirección, y su espectro JONSWAP muestreado en cuatro periodos, 11,2; 9,9; 8,8 y 6,1 s, que el fondo acorta cada uno por su lado; bajo 0,1 m de agua k se congela, donde las olas ya rompieron.',
    },
    references: ['airy1845', 'deanDalrymple1991', 'holthuijsen2007', 'hasselmann1973'],
  },
  'coast-refraction': {
    text: {
      en: 'Where one end of a crest is in shallower water it moves slower, and the crest turns towards the depth contours: refraction. Over the beach’s straight contours Snell’s law holds: the wavenumber along the shore, k sin θ, does not change, θ being the angle from the contours’ normal; so sin θ / c, c being the phase speed, is constant. A 10 s wave at θ₀ = 30° in 60 m of water turns to 17° at 10 m and to 8° at 2 m. Round the island the code solves instead the eikonal equation |∇S| = k(h) for the phase S on a grid, and rays traced across it give the height.',
      es: 'Donde un extremo de una cresta pisa aguas someras avanza más despacio, y la cresta gira hacia las isóbatas: la refracción. Sobre las isóbatas rectas de la playa rige la ley de Snell: el número de onda a lo largo de la costa, k sen θ, no cambia, con θ el ángulo con la normal a las isóbatas; así sen θ / c, con c la velocidad de fase, es constante. Una ola de 10 s a θ₀ = 30° en 60 m gira a 17° a 10 m y a 8° a 2 m. En la isla el código resuelve la ecuación eikonal |∇S| = k(h) para la fase S sobre una malla, y los rayos dan la altura.',
    },
    math:
      m(
        '<mi>k</mi><mi>sin</mi><mi>θ</mi><mo>=</mo><msub><mi>k</mi><mn>0</mn></msub><mi>sin</mi><msub><mi>θ</mi><mn>0</mn></msub><mspace width="0.5em"/><mo>⇔</mo><mspace width="0.5em"/><mfrac><mrow><mi>sin</mi><mi>θ</mi></mrow><mi>c</mi></mfrac><mo>=</mo><mfrac><mrow><mi>sin</mi><msub><mi>θ</mi><mn>0</mn></msub></mrow><msub><mi>c</mi><mn>0</mn></msub></mfrac>',
      ) + m('<mo>|</mo><mo>∇</mo><mi>S</mi><mo>|</mo><mo>=</mo><mi>k</mi><mo>(</mo><mi>h</mi><mo>)</mo>'),
    question: {
      ask: {
        en: 'The island hides the open sea from the water behind it. Will that water, in the island’s lee, be calm?',
        es: 'La isla tapa el mar abierto al agua que queda detrás. ¿Estará en calma esa agua, a sotavento de la isla?',
      },
      answer: {
        en: 'No: the crests turn towards the shallows all round the island and wrap round both sides, meeting behind it, where the code keeps the earlier of the two trains, so they meet in a kink rather than crossing. Only a strip just behind the island stays nearly calm: 300 m behind its shore the swell’s significant height is back above 1 m. Look at the lee from above.',
        es: 'No: las crestas giran hacia el agua somera alrededor de toda la isla y la rodean por ambos lados hasta encontrarse detrás, donde el código se queda con el primero de los dos trenes, así que se juntan en un pico en vez de cruzarse. Solo una franja justo detrás de la isla queda casi en calma: a 300 m de su orilla la altura significativa del oleaje vuelve a superar 1 m. Mira el sotavento desde arriba.',
      },
    },
    choice: {
      en: 'Geometric optics without diffraction: in the lee the earlier of two wrapped trains is kept, not their sum, and where rays focus Kr is capped at 2.5.',
      es: 'Óptica geométrica sin difracción: a sotavento se queda el primero de los dos trenes que rodean la isla, no su suma, y donde los rayos se concentran Kr se limita a 2,5.',
    },
    references: ['deanDalrymple1991', 'holthuijsen2007', 'arthurMunkIsaacs1952', 'zhao2005'],
  },
  'coast-shoaling': {
    text: {
      en: 'A wave carries energy E ∝ H² per square metre at its group velocity c_g, c/2 (1 + 2kh / sinh 2kh) for phase speed c, wavenumber k and depth h. With no loss before the break E c_g is kept, and H grows where c_g falls: H = H₀ K_s K_r, with the shoaling coefficient K_s = √(c_g0 / c_g) and K_r = 1 for a swell head-on. Each swell component shoals so: a 10 s wave of H₀ = 1.5 m, c_g0 at 60 m. K_s first dips: c_g grows from 8.25 m/s offshore to 9.37 m/s near 25 m, where K_s = 0.94. Then K_s = 1.14 at 5 m, where H = 1.71 m.',
      es: 'Una ola lleva una energía E ∝ H² por m² a su velocidad de grupo c_g = c/2 (1 + 2kh / senh 2kh), con c la velocidad de fase, k el número de onda y h la profundidad. Sin pérdidas, E c_g se conserva y H crece donde c_g baja: H = H₀ K_s K_r, con K_s = √(c_g0 / c_g), el coeficiente de asomeramiento, y K_r = 1 de frente. Cada componente del oleaje se asomera así; aquí, 10 s, H₀ = 1,5 m y c_g0 a 60 m. c_g crece de 8,25 m/s a 9,37 m/s cerca de 25 m, donde K_s = 0,94. Luego K_s = 1,14 a 5 m, donde H = 1,71 m.',
    },
    math:
      m(
        '<mi>H</mi><mo>=</mo><msub><mi>H</mi><mn>0</mn></msub><msub><mi>K</mi><mi>s</mi></msub><msub><mi>K</mi><mi>r</mi></msub><mo>,</mo><mspace width="0.5em"/><msub><mi>K</mi><mi>s</mi></msub><mo>=</mo><msqrt><mfrac><msub><mi>c</mi><mrow><mi>g</mi><mn>0</mn></mrow></msub><msub><mi>c</mi><mi>g</mi></msub></mfrac></msqrt>',
      ) +
      m(
        '<msub><mi>c</mi><mi>g</mi></msub><mo>=</mo><mfrac><mi>c</mi><mn>2</mn></mfrac><mrow><mo>(</mo><mn>1</mn><mo>+</mo><mfrac><mrow><mn>2</mn><mi>k</mi><mi>h</mi></mrow><mrow><mi>sinh</mi><mn>2</mn><mi>k</mi><mi>h</mi></mrow></mfrac><mo>)</mo></mrow><mo>,</mo><mspace width="0.5em"/><mi>E</mi><msub><mi>c</mi><mi>g</mi></msub><mo>=</mo><mtext>const</mtext><mo>,</mo><mspace width="0.5em"/><mi>E</mi><mo>∝</mo><msup><mi>H</mi><mn>2</mn></msup>',
      ),
    question: {
      ask: {
        en: 'As a 10 s wave of the swell leaves 60 m of water for 25 m, will it grow, shrink or keep its height?',
        es: 'Cuando una ola de 10 s del oleaje pasa de 60 m de profundidad a 25 m, ¿crece, mengua o conserva su altura?',
      },
      answer: {
        en: 'It shrinks, by about 6 %: at 25 m the wave is in intermediate water, where c_g, between half of c and all of it, is larger than offshore, so the same energy flux needs less height. It grows only inside about 11 m of water.',
        es: 'Mengua, un 6 % más o menos: a 25 m la ola está en aguas intermedias, donde c_g, entre la mitad de c y toda c, es mayor que mar adentro, así que el mismo flujo de energía pide menos altura. Solo crece a menos de unos 11 m de profundidad.',
      },
    },
    choice: {
      en: 'Linear theory up to the break: a real wave grows more peaked and steeper than K_s says just before it breaks.',
      es: 'Teoría lineal hasta la rotura: una ola real se vuelve más apuntada y empinada de lo que dice K_s justo antes de romper.',
    },
    references: ['deanDalrymple1991', 'holthuijsen2007', 'lamb1932'],
  },
  'coast-breaking': {
    text: {
      en: 'A wave breaks when its height reaches a fraction γ of the depth, the breaker index: H_b = γ h_b, with McCowan’s γ = 0.78. One 1.5 m, 10 s wave would grow to H = 1.98 m and break at h = 2.54 m, not at H₀/γ = 1.92 m, since it grows first. But the swell comes in sets: its four components add up to crests of 2 Σ A, so a set’s biggest waves break first, further out, at 3.24 m. Inside, H = γ h, and foam covers each breaking crest. At slope s = 0.02 the surf zone is x_surf = h_b / s ≈ 162 m wide.',
      es: 'Una ola rompe cuando su altura alcanza una fracción γ de la profundidad, el índice de rotura: H_b = γ h_b, con el γ = 0,78 de McCowan. Una ola de 1,5 m y 10 s crecería a H = 1,98 m y rompería a h = 2,54 m, no en H₀/γ = 1,92 m, porque antes crece. El oleaje llega en series: sus cuatro componentes suman crestas de 2 Σ A, así que las olas mayores de cada serie rompen primero, más afuera, a 3,24 m. Dentro, H = γ h, y la espuma cubre cada cresta que rompe. Con pendiente s = 0,02, la zona de rompientes mide x_surf = h_b / s ≈ 162 m.',
    },
    math:
      m(
        '<msub><mi>H</mi><mi>b</mi></msub><mo>=</mo><mi>γ</mi><msub><mi>h</mi><mi>b</mi></msub><mo>,</mo><mspace width="0.5em"/><mi>γ</mi><mo>=</mo><mn>0.78</mn><mo>,</mo><mspace width="0.5em"/><msub><mi>x</mi><mtext>surf</mtext></msub><mo>=</mo><mfrac><msub><mi>h</mi><mi>b</mi></msub><mi>s</mi></mfrac>',
      ) +
      m(
        '<mtext>breaking</mtext><mo>=</mo><mtext>smoothstep</mtext><mo>(</mo><mn>0.9</mn><mo>,</mo><mn>1</mn><mo>,</mo><mfrac><mi>H</mi><mrow><mi>γ</mi><mi>h</mi></mrow></mfrac><mo>)</mo>',
      ),
    question: {
      ask: {
        en: 'If you double Swell height from 1.5 to 3 m, will the surf zone grow twice as wide?',
        es: 'Si duplicas la altura del oleaje de 1,5 a 3 m, ¿la zona de rompientes se hace el doble de ancha?',
      },
      answer: {
        en: 'Not quite: with 3 m the set’s biggest waves break at h ≈ 5.80 m, so the surf zone is about 290 m wide, 1.79 times as wide: in deeper water a wave has shoaled less when it breaks. Move Swell height and watch the foam’s seaward edge.',
        es: 'No del todo: con 3 m las olas mayores de cada serie rompen a h ≈ 5,80 m, así que la zona de rompientes mide unos 290 m, 1,79 veces más: en agua más profunda una ola se ha asomerado menos al romper. Mueve la altura del oleaje y mira el borde de la espuma hacia el mar.',
      },
    },
    choice: {
      en: 'The limit acts on the envelope 2|Z| of the four components’ sum, a narrow-band sea’s wave height, saturating the surf as Thornton and Guza found on average; the foam fades in from 0.9 γ h, and its shape on the crest is artistic.',
      es: 'El límite actúa sobre la envolvente 2|Z| de la suma de las cuatro componentes, la altura de ola de un mar de banda estrecha, y satura la rompiente como hallaron en promedio Thornton y Guza; la espuma aparece desde 0,9 γ h, y su forma sobre la cresta es artística.',
    },
    references: ['mcCowan1894', 'thorntonGuza1983', 'battjesJanssen1978', 'hasselmann1973', 'holthuijsen2007'],
  },
};
