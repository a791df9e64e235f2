package io.concord.core.content;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import jade.content.abs.AbsContentElement;
import jade.content.lang.sl.SLCodec;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.util.TimeZone;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Property tests against JADE 4.3's own SLCodec and BeanOntology, over the same ontology
 * ({@link BookShop} and its JADE twin): random content written by one side is read by the other as
 * the same objects, and both write the same text. Cases per direction: the system property
 * {@code concord.sl.cases} (5,000 by default); the seed: {@code concord.sl.seed}.
 */
class SlJadeCompatibilityTest {
    private static final int CASES = Integer.getInteger("concord.sl.cases", 5_000);
    private static final long SEED = Long.getLong("concord.sl.seed", 33L);
    private static TimeZone savedZone;

    private final SlCodec codec = new SlCodec();
    private final BeanOntology ontology = BookShop.ontology();
    private final ContentManager manager = new ContentManager().register(codec).register(ontology);
    private final SLCodec jadeCodec = new SLCodec();
    private final jade.content.onto.Ontology jadeOntology;

    SlJadeCompatibilityTest() throws Exception {
        jadeOntology = JadeBookShop.ontology();
    }

    /** Dates must not depend on the machine's zone: run in one far from UTC. */
    @BeforeAll
    static void farFromUtc() {
        savedZone = TimeZone.getDefault();
        TimeZone.setDefault(TimeZone.getTimeZone("Asia/Kathmandu"));
    }

    @AfterAll
    static void restoreZone() {
        TimeZone.setDefault(savedZone);
    }

    @Test
    void jadeWritesAndConcordReadsTheSameObjects() throws Exception {
        ContentGenerator g = new ContentGenerator(SEED);
        int jadeCannotCarry = 0;
        for (int i = 0; i < CASES; i++) {
            Object content = g.contentElement();
            String jadeText = jadeWrite(content);
            if (!jadeCarries(content, jadeText)) {
                jadeCannotCarry++;
                continue;
            }
            Object read;
            try {
                AclMessage msg = new AclMessage(Performative.INFORM).setLanguage("fipa-sl").setOntology("book-shop")
                        .setContent(jadeText);
                read = manager.extract(msg);
            } catch (ContentException e) {
                throw new AssertionError("case " + i + " (seed " + SEED + "): Concord cannot read JADE's " + jadeText, e);
            }
            int n = i;
            assertEquals(JadeMapping.canon(content), JadeMapping.canon(read), () -> "case " + n + " (seed " + SEED + "): " + jadeText);
        }
        assertTrue(jadeCannotCarry <= CASES / 20, jadeCannotCarry + " of " + CASES + " cases JADE cannot carry itself");
    }

    @Test
    void concordWritesAndJadeReadsTheSameObjects() throws Exception {
        ContentGenerator g = new ContentGenerator(SEED + 1);
        for (int i = 0; i < CASES; i++) {
            Object content = g.contentElement();
            String text = codec.write(ontology.toAbs(content));
            Object read;
            try {
                AbsContentElement abs = jadeCodec.decode(jadeOntology, text);
                read = jadeOntology.toObject(abs);
            } catch (Exception e) {
                throw new AssertionError("case " + i + " (seed " + (SEED + 1) + "): JADE cannot read " + text, e);
            }
            assertEquals(JadeMapping.canon(content), JadeMapping.canon(read), "case " + i + ": " + text);
        }
    }

    /**
     * Wherever JADE's own text means what it should (JADE reads it back as the same objects),
     * Concord writes exactly that text. Where it does not (JADE leaves {@code .5} or {@code +1}
     * bare and then reads a number), Concord quotes; such cases are counted, and must be rare.
     */
    @Test
    void concordWritesTheBytesJadeWrites() throws Exception {
        ContentGenerator g = new ContentGenerator(SEED + 2);
        int jadeCannotCarry = 0;
        for (int i = 0; i < CASES; i++) {
            Object content = g.contentElement();
            String jadeText = jadeWrite(content);
            if (!jadeCarries(content, jadeText)) {
                jadeCannotCarry++;
                continue;
            }
            assertEquals(jadeText, codec.write(ontology.toAbs(content)), "case " + i + " (seed " + (SEED + 2) + ")");
        }
        assertTrue(jadeCannotCarry <= CASES / 20, jadeCannotCarry + " of " + CASES + " cases JADE cannot carry itself");
    }

    /** Whether JADE reads its own text back as the content it wrote (not for some strings: see SlCodec). */
    private boolean jadeCarries(Object content, String jadeText) {
        try {
            Object back = jadeOntology.toObject(jadeCodec.decode(jadeOntology, jadeText));
            return JadeMapping.canon(content).equals(JadeMapping.canon(back));
        } catch (Exception e) {
            return false;
        }
    }

    private String jadeWrite(Object content) throws Exception {
        Object jade = JadeMapping.toJade(content);
        return jadeCodec.encode(jadeOntology, (AbsContentElement) jadeOntology.fromObject(jade));
    }
}
