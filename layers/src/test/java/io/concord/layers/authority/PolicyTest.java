package io.concord.layers.authority;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The authority table: the code's is the one docs/security.md shows, default deny, and what may be opened. */
class PolicyTest {

    @Test
    void theDocumentsTableIsTheCodes() throws Exception {
        List<String> doc = Files.readAllLines(Path.of("..", "docs", "security.md"));
        for (String row : Policy.table()) {
            assertTrue(doc.contains(row), "docs/security.md's 'Who may do what' lacks, or differs from, the row: " + row);
        }
    }

    @Test
    void aForeignAgentReachesOnlyWhatAJadeAgentNeeds() {
        Policy p = Policy.defaults();
        for (Policy.Service s : Policy.Service.values()) {
            boolean jadeNeeds = s == Policy.Service.AGENT_MESSAGE || s == Policy.Service.DF || s == Policy.Service.AMS;
            assertEquals(jadeNeeds, p.allows(Policy.Principal.FOREIGN, s), s.key());
            assertFalse(p.allows(Policy.Principal.KEY_HOLDER, s), "a key holder reaches no service: " + s.key());
        }
        assertFalse(p.allows(Policy.Principal.MEMBER, Policy.Service.CHAIR_RESUME), "the platform key makes no operator");
        assertTrue(p.allows(Policy.Principal.OPERATOR, Policy.Service.CHAIR_RESUME));
        assertTrue(p.decide(Policy.Principal.FOREIGN, Policy.Service.OBSERVE_KILL).reason().contains("-http-expose kill"));
        assertTrue(Policy.allowingEverything().allows(Policy.Principal.FOREIGN, Policy.Service.CHAIR_RESUME), "the tests' switch");
    }

    @Test
    void anOperatorOpensOnlyTheObservationServiceByName() {
        Policy p = Policy.exposing("status, sniff");
        assertTrue(p.allows(Policy.Principal.FOREIGN, Policy.Service.OBSERVE_STATUS));
        assertTrue(p.allows(Policy.Principal.FOREIGN, Policy.Service.OBSERVE_SNIFF));
        assertFalse(p.allows(Policy.Principal.FOREIGN, Policy.Service.OBSERVE_KILL));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Policy.exposing("platform")).getMessage()
                .contains("platform cannot be exposed"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Policy.exposing("everything")).getMessage()
                .contains("no service 'everything'"));
    }

    @Test
    void aMessageSaysWhoSentItAndWhatItAsks() {
        AclMessage kill = new AclMessage(Performative.REQUEST).setSender(new AID("killer@elsewhere"));
        kill.setOntology(Policy.OBSERVE_ONTOLOGY);
        kill.setContent("kill");
        assertEquals(Policy.Principal.FOREIGN, Policy.principalOf(kill, "hospital"));
        assertEquals(Policy.Service.OBSERVE_KILL, Policy.serviceOf(kill));
        kill.setSender(new AID("console@Hospital"));
        assertEquals(Policy.Principal.MEMBER, Policy.principalOf(kill, "hospital"));
        AclMessage words = new AclMessage(Performative.INFORM).setSender(new AID("x@elsewhere"));
        words.setOntology("concord-services");
        assertEquals(Policy.Service.PLATFORM_MESSAGE, Policy.serviceOf(words));
        assertEquals(Policy.Principal.FOREIGN, Policy.principalOf(new AclMessage(Performative.INFORM), "hospital"), "no sender");
    }

    @Test
    void anOrderIsGoodOnceForItsChairFromAKnownKey() {
        OperatorKey ada = OperatorKey.generate("nurse Ada");
        Operators ward = Operators.of(ada.operator());
        long now = 1_800_000_000_000L;
        SignedOrder o = SignedOrder.parse(ada.sign("resume", "chair1", now).encode());
        assertNull(ward.verify(o, "resume", "chair1", now + 1_000));
        assertTrue(ward.verify(o, "resume", "chair1", now + 2_000).contains("a replay"));
        assertTrue(ward.verify(ada.sign("resume", "chair1", now + 20_000), "resume", "chair1", now).contains("ahead"));
        assertTrue(Operators.none().verify(ada.sign("resume", "chair1", now), "resume", "chair1", now).contains("has none configured"));
    }

    @Test
    void anOperatorKeyFileIsTheOwnersAloneAndReadsBack(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("ada.key");
        OperatorKey k = OperatorKey.loadOrCreate(f, "nurse Ada", s -> { });
        assertEquals(k.operator(), OperatorKey.load(f).operator());
        assertNull(Operators.read(f).verify(k.sign("resume", "c", 5), "resume", "c", 5), "a ward reads the key file's public line");
        assertTrue(assertThrows(IllegalArgumentException.class, () -> k.save(f)).getMessage().contains("never written over"));
        Files.setPosixFilePermissions(f, PosixFilePermissions.fromString("rw-r--r--"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> OperatorKey.load(f)).getMessage().contains("chmod 600"));
        Path junk = dir.resolve("junk.key");
        Files.writeString(junk, "hello\n");
        Files.setPosixFilePermissions(junk, PosixFilePermissions.fromString("rw-------"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> OperatorKey.load(junk)).getMessage().contains("is not an operator key"));
    }
}
