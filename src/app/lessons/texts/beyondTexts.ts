import type { LessonText } from './lessonText';
import { m } from './mathml';

/** The cards of the models compared, the physics panel, the wake, the interactive waves and the horizon. */
export const beyondTexts: Record<string, LessonText> = {
  'compare-models': {
    text: {
      en: 'The three wave models side by side, on one camera and one noise seed. Left, the seed’s sines and its octaves of value noise (the report calls them Perlin); middle, 32 Gerstner trochoids drawn from the wind spectrum; right, Tessendorf’s FFT of the same spectrum. Only the middle and right models follow the 10 m/s wind: the seed’s waves read no wind at all. Each model draws only its strip of the screen. A divider at fraction f of the part of the view the panels leave free, from pixel column x₀ to x₁, stands on the column below. Drag the dividers, or move them with the arrow keys.',
      es: 'Los tres modelos de olas lado a lado, con una cámara y una semilla de ruido. A la izquierda, los senos del informe y sus octavas de ruido de valor (el informe lo llama Perlin); en el centro, 32 trocoides de Gerstner tomadas del espectro del viento; a la derecha, la FFT de Tessendorf del mismo espectro. Solo el centro y la derecha siguen el viento de 10 m/s: las olas del informe no leen el viento. Cada modelo dibuja solo su franja. Un divisor en la fracción f de la parte libre de la vista, de la columna de píxeles x₀ a x₁, queda en la columna de abajo. Arrastra los divisores o muévelos con las flechas.',
    },
    math: m(
      '<msub><mi>x</mi><mtext>split</mtext></msub><mo>=</mo><mtext>round</mtext><mo>(</mo><msub><mi>x</mi><mn>0</mn></msub><mo>+</mo><mi>f</mi><mo>·</mo><mo>(</mo><msub><mi>x</mi><mn>1</mn></msub><mo>−</mo><msub><mi>x</mi><mn>0</mn></msub><mo>)</mo><mo>)</mo>',
    ),
    question: {
      ask: {
        en: 'If you raise Wind speed from 10 to 20 m/s, which strips will change their waves, and which will not?',
        es: 'Si subes la velocidad del viento de 10 a 20 m/s, ¿qué franjas cambian sus olas y cuáles no?',
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
      m(
        '<msub><mi>H</mi><mi>s</mi></msub><mo>=</mo><mn>4</mn><msub><mi>σ</mi><mi>η</mi></msub><mo>≈</mo><mn>4</mn><msqrt><msub><mi>m</mi><mn>0</mn></msub></msqrt><mo>≈</mo><mn>0.21</mn><mfrac><msubsup><mi>U</mi><mn>19.5</mn><mn>2</mn></msubsup><mi>g</mi></mfrac>',
      ) +
      m(
        '<msub><mi>T</mi><mi>p</mi></msub><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi></mrow><msub><mi>ω</mi><mi>p</mi></msub></mfrac><mo>,</mo><mspace width="0.5em"/><msub><mi>ω</mi><mi>p</mi></msub><mo>=</mo><mn>0.877</mn><mfrac><mi>g</mi><msub><mi>U</mi><mn>19.5</mn></msub></mfrac><mo>,</mo><mspace width="0.5em"/><msub><mi>U</mi><mn>19.5</mn></msub><mo>=</mo><mn>1.026</mn><msub><mi>U</mi><mn>10</mn></msub>',
      ),
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
      m(
        '<msub><mi>λ</mi><mtext>t</mtext></msub><mo>=</mo><mfrac><mrow><mn>2</mn><mi>π</mi><msup><mi>U</mi><mn>2</mn></msup></mrow><mi>g</mi></mfrac><mo>≈</mo><mn>10.2</mn><mspace width="0.2em"/><mtext>m</mtext>',
      ) +
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
      m(
        '<mi>η</mi><mo>(</mo><mi mathvariant="bold">x</mi><mo>)</mo><mo>=</mo><munder><mo>∑</mo><mi>j</mi></munder><mi>Δ</mi><msub><mi>τ</mi><mi>j</mi></msub><mspace width="0.1em"/><mi>G</mi><mo>(</mo><mo>|</mo><mi mathvariant="bold">x</mi><mo>−</mo><msub><mi mathvariant="bold">x</mi><mi>j</mi></msub><mo>|</mo><mo>,</mo><msub><mi>τ</mi><mi>j</mi></msub><mo>)</mo>',
      ) +
      m(
        '<mi>G</mi><mo>(</mo><mi>r</mi><mo>,</mo><mi>τ</mi><mo>)</mo><mo>∝</mo><mfrac><msup><mi>τ</mi><mn>3</mn></msup><msup><mi>r</mi><mn>4</mn></msup></mfrac><msup><mi>e</mi><mrow><mo>−</mo><msup><mi>k</mi><mn>2</mn></msup><msup><mi>σ</mi><mn>2</mn></msup><mo>/</mo><mn>4</mn></mrow></msup><mi>sin</mi><mfrac><mrow><mi>g</mi><msup><mi>τ</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><mi>r</mi></mrow></mfrac><mo>,</mo><mspace width="0.5em"/><mi>k</mi><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>τ</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><msup><mi>r</mi><mn>2</mn></msup></mrow></mfrac>',
      ),
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
      m(
        '<mi>η</mi><mo>(</mo><mi mathvariant="bold">x</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>=</mo><munder><mo>∑</mo><mi mathvariant="bold">k</mi></munder><mo>[</mo><msub><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn></msub><mo>(</mo><mi mathvariant="bold">k</mi><mo>)</mo><msup><mi>e</mi><mrow><mi>i</mi><mi>ω</mi><mi>t</mi></mrow></msup><mo>+</mo><msubsup><mover><mi>h</mi><mo>~</mo></mover><mn>0</mn><mo>*</mo></msubsup><mo>(</mo><mo>−</mo><mi mathvariant="bold">k</mi><mo>)</mo><msup><mi>e</mi><mrow><mo>−</mo><mi>i</mi><mi>ω</mi><mi>t</mi></mrow></msup><mo>]</mo><msup><mi>e</mi><mrow><mi>i</mi><mi mathvariant="bold">k</mi><mo>·</mo><mi mathvariant="bold">x</mi></mrow></msup>',
      ) +
      m(
        '<msup><mi>h</mi><mrow><mi>n</mi><mo>+</mo><mn>1</mn></mrow></msup><mo>=</mo><mfrac><mrow><mn>2</mn><msup><mi>h</mi><mi>n</mi></msup><mo>−</mo><mo>(</mo><mn>1</mn><mo>−</mo><mfrac><mrow><mi>α</mi><mi>Δ</mi><mi>t</mi></mrow><mn>2</mn></mfrac><mo>)</mo><msup><mi>h</mi><mrow><mi>n</mi><mo>−</mo><mn>1</mn></mrow></msup><mo>−</mo><mfrac><mrow><mi>g</mi><mi>Δ</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mi>Δ</mi><mi>x</mi></mrow></mfrac><mo>(</mo><mi>G</mi><mo>∗</mo><msup><mi>h</mi><mi>n</mi></msup><mo>)</mo></mrow><mrow><mn>1</mn><mo>+</mo><mfrac><mrow><mi>α</mi><mi>Δ</mi><mi>t</mi></mrow><mn>2</mn></mfrac></mrow></mfrac>',
      ),
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
      m(
        '<mi>k</mi><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mn>4</mn><msup><mi>r</mi><mn>2</mn></msup></mrow></mfrac>',
      ) +
      m(
        '<msub><mi>r</mi><mi>n</mi></msub><mo>=</mo><mfrac><mrow><mi>g</mi><msup><mi>t</mi><mn>2</mn></msup></mrow><mrow><mn>8</mn><mi>π</mi><mi>n</mi></mrow></mfrac>',
      ),
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
      m(
        '<mfrac><mrow><msup><mo>∂</mo><mn>2</mn></msup><mi>h</mi></mrow><mrow><mo>∂</mo><msup><mi>t</mi><mn>2</mn></msup></mrow></mfrac><mo>=</mo><mo>−</mo><mi>g</mi><msqrt><mo>−</mo><msup><mo>∇</mo><mn>2</mn></msup></msqrt><mi>h</mi><mspace width="1em"/><mo>⇒</mo><mspace width="1em"/><msup><mi>ω</mi><mn>2</mn></msup><mo>=</mo><mi>g</mi><mi>k</mi>',
      ) +
      m(
        '<mfrac><mrow><msup><mo>∂</mo><mn>2</mn></msup><mi>h</mi></mrow><mrow><mo>∂</mo><msup><mi>t</mi><mn>2</mn></msup></mrow></mfrac><mo>=</mo><msup><mi>c</mi><mn>2</mn></msup><msup><mo>∇</mo><mn>2</mn></msup><mi>h</mi><mspace width="1em"/><mo>⇒</mo><mspace width="1em"/><mi>ω</mi><mo>=</mo><mi>c</mi><mi>k</mi><mo>,</mo><mspace width="0.5em"/><mi>c</mi><mo>=</mo><msqrt><mfrac><mi>g</mi><mrow><mn>1.5</mn><mspace width="0.1em"/><mtext>rad/m</mtext></mrow></mfrac></msqrt><mo>=</mo><mn>2.56</mn><mspace width="0.2em"/><mtext>m/s</mtext>',
      ),
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
      m(
        '<mi>Q</mi><mo>=</mo><mfrac><mrow><mi>U</mi><mi>V</mi></mrow><mi>L</mi></mfrac><mo>=</mo><mn>3.2</mn><mspace width="0.2em"/><msup><mtext>m</mtext><mn>3</mn></msup><mtext>/s</mtext>',
      ) +
      m(
        '<mi>D</mi><mo>=</mo><mi>max</mi><mo>(</mo><mn>2</mn><mi>L</mi><mo>,</mo><mfrac><mrow><mn>2</mn><mi>π</mi><msup><mi>U</mi><mn>2</mn></msup></mrow><mi>g</mi></mfrac><mo>)</mo><mo>=</mo><mn>16</mn><mspace width="0.2em"/><mtext>m</mtext>',
      ),
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
      m(
        '<msub><mi>β</mi><mn>0</mn></msub><mo>=</mo><mfrac><mrow><mi>ln</mi><mspace width="0.17em"/><mn>50</mn></mrow><mi>V</mi></mfrac><mo>≈</mo><mfrac><mn>3.912</mn><mi>V</mi></mfrac><mo>,</mo><mspace width="0.5em"/><mi>β</mi><mo>(</mo><mi>y</mi><mo>)</mo><mo>=</mo><msub><mi>β</mi><mn>0</mn></msub><msup><mi>e</mi><mrow><mo>−</mo><mi>y</mi><mo>/</mo><mi>H</mi></mrow></msup>',
      ),
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
};
