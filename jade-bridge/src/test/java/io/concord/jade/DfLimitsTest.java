package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.content.Action;
import io.concord.core.content.FipaAgentManagement;
import io.concord.core.content.FipaAgentManagement.DfAgentDescription;
import io.concord.core.content.FipaAgentManagement.Register;
import io.concord.core.content.FipaAgentManagement.Deregister;
import io.concord.core.content.FipaAgentManagement.Search;
import io.concord.core.content.FipaAgentManagement.SearchConstraints;
import io.concord.core.content.SlCodec;
import io.concord.layers.platform.AgentEntry;
import io.concord.layers.platform.GatewayContext;
import io.concord.layers.platform.ServiceDescription;
import org.junit.jupiter.api.Test;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * What agents of other platforms can make the DF hold: registrations per sender and in all, lease
 * times honoured, search answers capped (JADE's max-results). The DF's own answers to the requests
 * JADE's DFService writes, on an injected clock.
 */
class DfLimitsTest {
    private static final SlCodec SL = new SlCodec();
    private final AtomicLong now = new AtomicLong(1_800_000_000_000L);
    private final List<String> refusals = new ArrayList<>();
    private final AgentManagement df = new AgentManagement(() -> List.of("http://127.0.0.1:7779/acc"), now::get,
            AgentManagement.Limits.DEFAULT, (r, why) -> refusals.add(r));

    private final GatewayContext platform = new GatewayContext() {
        @Override public String platformName() { return "ourplat"; }
        @Override public void execute(Runnable task) { task.run(); }
        @Override public boolean deliver(AclMessage message, AID receiver) { return false; }
        @Override public List<AgentEntry> search(List<ServiceDescription> templates) { return List.of(); }
        @Override public List<AgentEntry> agents() { return List.of(); }
    };

    private AclMessage ask(String sender, Object what) throws Exception {
        AclMessage m = new AclMessage(Performative.REQUEST).setSender(new AID(sender, "http://127.0.0.1:9/acc"));
        m.setLanguage("fipa-sl0");
        m.setOntology(FipaAgentManagement.NAME);
        m.setContent(SL.write(FipaAgentManagement.ontology().toAbs(new Action(new AID("df@ourplat"), what))));
        return df.answer(platform, m, true);
    }

    private static DfAgentDescription entry(String name, Instant lease) {
        return new DfAgentDescription(new AID(name), Set.of(new FipaAgentManagement.ServiceDescription("s-" + name, "book-selling",
                null, null, null, null, null)), null, null, null, lease);
    }

    private AclMessage register(String sender, String name, Instant lease) throws Exception {
        return ask(sender, new Register(entry(name, lease)));
    }

    private int found(Long maxResults) throws Exception {
        AclMessage r = ask("seeker@elsewhere", new Search(new DfAgentDescription(null, null, null, null, null, null),
                new SearchConstraints(null, maxResults, null)));
        assertEquals(Performative.INFORM, r.getPerformative(), r.getContent());
        return r.getContent().split("df-agent-description", -1).length - 2;   // the first is the search template, echoed
    }

    @Test
    void anAgentOfAnotherPlatformRegistersItselfOnlyAndNoneOfThisPlatform() throws Exception {
        for (int i = 0; i < 30_000; i++) {
            AclMessage r = register("flooder@elsewhere", "a" + i + "@elsewhere", null);
            assertEquals(Performative.FAILURE, r.getPerformative(), r.getContent());
        }
        AclMessage r = register("flooder@elsewhere", "a1@elsewhere", null);
        assertTrue(r.getContent().contains("registers itself only"), r.getContent());
        assertEquals(0, df.registrations(), "30,000 names another agent's: none taken");
        r = register("s1@ourplat", "s1@ourplat", null);
        assertEquals(Performative.FAILURE, r.getPerformative());
        assertTrue(r.getContent().contains("is an agent of this platform"), "no squatting on a Concord agent's name: " + r.getContent());
        assertEquals(Performative.INFORM, register("flooder@elsewhere", "flooder@elsewhere", null).getPerformative());
        assertEquals(Performative.INFORM, register("flooder@elsewhere", "flooder@elsewhere", null).getPerformative(), "again: replaced");
        assertEquals(1, df.registrations());
    }

    @Test
    void manySendersFillAtMostTheTotalAndSearchesAnswerAPage() throws Exception {
        int ok = 0;
        for (int i = 0; i < 30_000; i++) {
            if (register("s" + i + "@elsewhere", "s" + i + "@elsewhere", null).getPerformative() == Performative.INFORM) {
                ok++;
            }
        }
        assertEquals(AgentManagement.Limits.DEFAULT.total(), ok, "refused past the total");
        assertEquals(AgentManagement.Limits.DEFAULT.total(), df.registrations());
        assertEquals(30_000 - ok, refusals.size(), "each refusal for the limit counted");
        assertEquals(AgentManagement.Limits.DEFAULT.defaultResults(), found(null), "JADE's default max-results");
        assertEquals(10, found(10L));
        assertEquals(AgentManagement.Limits.DEFAULT.maxResults(), found(1_000_000L), "never past the cap");
    }

    @Test
    void aLeaseThatEndsRemovesTheRegistrationAndFreesItsPlace() throws Exception {
        assertEquals(Performative.INFORM, register("buyer@elsewhere", "buyer@elsewhere", Instant.ofEpochMilli(now.get() + 60_000)).getPerformative());
        assertEquals(Performative.INFORM, register("seller@elsewhere", "seller@elsewhere", null).getPerformative());
        assertEquals(2, found(null));
        now.addAndGet(60_000);
        assertEquals(1, found(null), "the lease ended: the buyer is gone, the seller (no lease) stays");
        assertEquals(1, df.registrations());
        assertEquals(Performative.FAILURE, register("late@elsewhere", "late@elsewhere", Instant.ofEpochMilli(now.get() - 1)).getPerformative(),
                "a lease already over");
    }

    @Test
    void anAgentCannotTakeOverOrRemoveAnotherOnesRegistration() throws Exception {
        assertEquals(Performative.INFORM, register("seller@elsewhere", "seller@elsewhere", null).getPerformative());
        AclMessage r = register("mallory@elsewhere", "seller@elsewhere", null);
        assertEquals(Performative.FAILURE, r.getPerformative());
        assertTrue(r.getContent().contains("registers itself only"), r.getContent());
        r = ask("mallory@elsewhere", new Deregister(entry("seller@elsewhere", null)));
        assertEquals(Performative.FAILURE, r.getPerformative());
        assertTrue(r.getContent().contains("unauthorised"), r.getContent());
        assertEquals(Performative.INFORM, ask("seller@elsewhere", new Deregister(entry("seller@elsewhere", null))).getPerformative());
        assertEquals(0, df.registrations());
    }
}
