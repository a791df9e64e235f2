package io.concord.bench.jmh;

import io.concord.bench.jade.JadeOrderOntology;
import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.content.Action;
import io.concord.core.content.AgentAction;
import io.concord.core.content.BeanOntology;
import io.concord.core.content.BinaryContentCodec;
import io.concord.core.content.Concept;
import io.concord.core.content.ContentManager;
import io.concord.core.content.SlCodec;
import jade.content.lang.sl.SLCodec;
import jade.lang.acl.ACLMessage;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

import java.time.Instant;
import java.util.List;

/**
 * Issue 33: fill + extract of one 10-slot agent action inside {@code (action ...)}: Concord's SL,
 * Concord's binary content, and JADE 4.3's SLCodec with its BeanOntology, in the same run.
 */
@State(Scope.Benchmark)
public class ContentBenchmark {
    /** Concord's SL codec. */
    public static final String CONCORD_SL = "concord-sl";
    /** Concord's binary content codec. */
    public static final String CONCORD_BINARY = "concord-binary";
    /** JADE's SLCodec and BeanOntology. */
    public static final String JADE_SL = "jade-sl";

    @Param({CONCORD_SL, CONCORD_BINARY, JADE_SL})
    public String codec;

    /** Where to deliver. */
    public record Address(String city, String street) implements Concept {
    }

    /** The 10-slot action, Concord's twin of {@link JadeOrderOntology.Order}. */
    public record Order(String title, long quantity, int edition, double price, float rating, boolean express,
                        Instant due, List<String> tags, String note, Address address) implements AgentAction {
    }

    private ContentManager concord;
    private Action concordContent;
    private jade.content.ContentManager jadeManager;
    private jade.content.onto.basic.Action jadeContent;

    @Setup
    public void setUp() throws Exception {
        AID me = new AID("buyer@P", "http://localhost:7778/acc");
        concordContent = new Action(me, new Order("The \"Agents\" Book", 3, 2, 49.95, 4.5f, true,
                Instant.ofEpochMilli(1_700_000_000_123L), List.of("agents", "fipa", "sl"), "leave at door",
                new Address("Lisbon", "1 Main Street")));
        BeanOntology ontology = new BeanOntology("orders", Address.class, Order.class);
        concord = new ContentManager().register(ontology);
        if (codec.equals(CONCORD_BINARY)) {
            concord.register(new BinaryContentCodec());
        } else {
            concord.register(new SlCodec());
        }
        jadeManager = new jade.content.ContentManager();
        jadeManager.registerLanguage(new SLCodec());
        jadeManager.registerOntology(JadeOrderOntology.ontology());
        jade.core.AID jadeMe = new jade.core.AID("buyer@P", jade.core.AID.ISGUID);
        jadeMe.addAddresses("http://localhost:7778/acc");
        jadeContent = new jade.content.onto.basic.Action(jadeMe, JadeOrderOntology.sample());
    }

    /** One fill and one extract; returns what was extracted, so nothing is optimised away. */
    @Benchmark
    public Object fillAndExtract() throws Exception {
        if (codec.equals(JADE_SL)) {
            ACLMessage msg = new ACLMessage(ACLMessage.REQUEST);
            msg.setLanguage("fipa-sl");
            msg.setOntology("orders");
            jadeManager.fillContent(msg, jadeContent);
            return jadeManager.extractContent(msg);
        }
        AclMessage msg = new AclMessage(Performative.REQUEST);
        concord.fill(msg, concordContent);
        return concord.extract(msg);
    }
}
