package io.concord.jadecompat;

import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.domain.JavaMethod;
import com.tngtech.archunit.core.domain.JavaModifier;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * A JADE-named method that compiles but does nothing is the worst kind of gap: JADE code calls it
 * and nothing happens. Every public or protected method of a {@code jade.*} class here must
 * reach something (a field, another method, a constructor: Concord's engine in the end), unless
 * JADE documents it as a no-op default or a constant; those are listed below, each with why.
 */
class NoSilentMethodsTest {
    /** JADE's documented no-op defaults and constants: a user overrides the hooks; the rest are what JADE returns too. */
    static final Map<String, String> DOCUMENTED_NO_OPS = new TreeMap<>(Map.ofEntries(
            Map.entry("jade.core.Agent.setup", "JADE: empty default, the user's hook"),
            Map.entry("jade.core.Agent.takeDown", "JADE: empty default, the user's hook"),
            Map.entry("jade.core.Agent.beforeMove", "JADE: empty default; agents do not move here"),
            Map.entry("jade.core.Agent.afterMove", "JADE: empty default; agents do not move here"),
            Map.entry("jade.core.Agent.beforeClone", "JADE: empty default; agents are not cloned here"),
            Map.entry("jade.core.Agent.afterClone", "JADE: empty default; agents are not cloned here"),
            Map.entry("jade.core.behaviours.Behaviour.onStart", "JADE: empty default, the user's hook"),
            Map.entry("jade.core.behaviours.Behaviour.onEnd", "JADE: returns 0 by default"),
            Map.entry("jade.core.behaviours.WakerBehaviour.onWake", "JADE: empty default, the user's hook"),
            Map.entry("jade.core.behaviours.OneShotBehaviour.done", "JADE: always true"),
            Map.entry("jade.core.behaviours.CyclicBehaviour.done", "JADE: always false"),
            Map.entry("jade.proto.AchieveREResponder.done", "a responder never ends, as JADE's"),
            Map.entry("jade.proto.ContractNetResponder.done", "a responder never ends, as JADE's"),
            Map.entry("jade.proto.AchieveREInitiator.handleAgree", "JADE: empty default handler (ProtocolHandlersTest shows it is called)"),
            Map.entry("jade.proto.AchieveREInitiator.handleRefuse", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.AchieveREInitiator.handleNotUnderstood", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.AchieveREInitiator.handleInform", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.AchieveREInitiator.handleFailure", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.AchieveREInitiator.handleOutOfSequence", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.AchieveREInitiator.handleAllResponses", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.AchieveREInitiator.handleAllResultNotifications", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetInitiator.handlePropose", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetInitiator.handleRefuse", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetInitiator.handleNotUnderstood", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetInitiator.handleFailure", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetInitiator.handleInform", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetInitiator.handleOutOfSequence", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetInitiator.handleAllResponses", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetInitiator.handleAllResultNotifications", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetResponder.prepareResponse", "JADE: older name of handleCfp, null by default (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetResponder.prepareResultNotification", "JADE: older name of handleAcceptProposal, null by default (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetResponder.handleRejectProposal", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetResponder.handleOutOfSequence", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ContractNetResponder.sessionTerminated", "JADE: empty default hook (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SubscriptionInitiator.handleAgree", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SubscriptionInitiator.handleRefuse", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SubscriptionInitiator.handleNotUnderstood", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SubscriptionInitiator.handleInform", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SubscriptionInitiator.handleFailure", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SubscriptionInitiator.handleOutOfSequence", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SubscriptionInitiator.handleAllResponses", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SubscriptionInitiator.cancellationCompleted", "JADE: empty default hook (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SubscriptionResponder.done", "a responder never ends, as JADE's"),
            Map.entry("jade.proto.ProposeInitiator.handleAcceptProposal", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ProposeInitiator.handleRejectProposal", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ProposeInitiator.handleNotUnderstood", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ProposeInitiator.handleOutOfSequence", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ProposeInitiator.handleAllResponses", "JADE: empty default handler (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.ProposeResponder.done", "a responder never ends, as JADE's"),
            Map.entry("jade.proto.ProposeResponder.prepareResponse", "no answer by default (called: ProtocolHandlersTest)"),
            Map.entry("jade.proto.SSContractNetResponder.handleCfp", "JADE: no answer by default (null), the user's hook"),
            Map.entry("jade.proto.SSContractNetResponder.handleAcceptProposal", "JADE: no result by default (null), the user's hook"),
            Map.entry("jade.proto.SSContractNetResponder.handleRejectProposal", "JADE: empty default handler"),
            Map.entry("jade.proto.SSContractNetResponder.handleOutOfSequence", "JADE: empty default handler"),
            Map.entry("jade.proto.SSContractNetResponder.beforeReply", "JADE: empty default hook (SSResponder)"),
            Map.entry("jade.proto.SSContractNetResponder.afterReply", "JADE: empty default hook (SSResponder)"),
            Map.entry("jade.proto.SimpleAchieveREInitiator.prepareRequest", "JADE: the request as given, by default"),
            Map.entry("jade.proto.states.MsgReceiver.handleMessage", "JADE: empty default hook"),
            Map.entry("jade.core.Runtime.getVersion", "a constant: the JADE API version this jar follows"),
            Map.entry("jade.core.Runtime.getRevision", "a constant"),
            Map.entry("jade.core.Runtime.getDate", "a constant"),
            Map.entry("jade.core.Runtime.getCopyrightNotice", "a constant: says this is not JADE"),
            Map.entry("jade.core.ContainerID.getProtocol", "a constant: the platform's transport"),
            Map.entry("jade.content.abs.AbsAgentAction.getAbsType", "a constant: the descriptor's kind, one of JADE's AbsObject constants"),
            Map.entry("jade.content.abs.AbsAggregate.getAbsType", "a constant: the descriptor's kind, one of JADE's AbsObject constants"),
            Map.entry("jade.content.abs.AbsConcept.getAbsType", "a constant: the descriptor's kind, one of JADE's AbsObject constants"),
            Map.entry("jade.content.abs.AbsContentElementList.getAbsType", "a constant: the descriptor's kind, one of JADE's AbsObject constants"),
            Map.entry("jade.content.abs.AbsObjectImpl.getAbsType", "a constant: the descriptor's kind, one of JADE's AbsObject constants"),
            Map.entry("jade.content.abs.AbsPredicate.getAbsType", "a constant: the descriptor's kind, one of JADE's AbsObject constants"),
            Map.entry("jade.content.abs.AbsPrimitive.getAbsType", "a constant: the descriptor's kind, one of JADE's AbsObject constants"),
            Map.entry("jade.content.abs.AbsVariable.getAbsType", "a constant: the descriptor's kind, one of JADE's AbsObject constants"),
            Map.entry("jade.content.abs.AbsAgentAction.getJavaClass", "a constant: the descriptor class, as JADE returns it"),
            Map.entry("jade.content.abs.AbsConcept.getJavaClass", "a constant: the descriptor class, as JADE returns it"),
            Map.entry("jade.content.abs.AbsPredicate.getJavaClass", "a constant: the descriptor class, as JADE returns it"),
            Map.entry("jade.content.abs.AbsVariable.getJavaClass", "a constant: the descriptor class, as JADE returns it"),
            Map.entry("jade.content.abs.AbsContentElementList.getTypeName", "a constant: BasicOntology.CONTENT_ELEMENT_LIST, as JADE"),
            Map.entry("jade.content.abs.AbsPrimitive.getAbsObject", "JADE: a primitive has no slot (null)"),
            Map.entry("jade.content.abs.AbsPrimitive.getCount", "JADE: a primitive has no slot (0)"),
            Map.entry("jade.content.abs.AbsPrimitive.getNames", "JADE: a primitive has no slot (no names)"),
            Map.entry("jade.content.abs.AbsIRE.getAbsType", "a constant: the descriptor's kind, one of JADE's AbsObject constants"),
            Map.entry("jade.content.abs.AbsIRE.getJavaClass", "a constant: the descriptor class, as JADE returns it"),
            Map.entry("jade.content.abs.AbsVariable.isGrounded", "JADE: a variable is never grounded (false)")));

    private static JavaClasses classes;

    @BeforeAll
    static void importCompatClasses() throws Exception {
        Path compat = Path.of(jade.core.Agent.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        classes = new ClassFileImporter().importPath(compat);
    }

    private static boolean reachesNothing(JavaMethod m) {
        return m.getAccessesFromSelf().isEmpty() && m.getCallsFromSelf().isEmpty();
    }

    private static boolean userVisible(JavaMethod m) {
        Set<JavaModifier> mods = m.getModifiers();
        return (mods.contains(JavaModifier.PUBLIC) || mods.contains(JavaModifier.PROTECTED))
                && !mods.contains(JavaModifier.ABSTRACT) && !mods.contains(JavaModifier.SYNTHETIC) && !mods.contains(JavaModifier.BRIDGE);
    }

    @Test
    void everyJadeMethodReachesSomethingUnlessJadeDocumentsItAsANoOp() {
        Set<String> silent = new TreeSet<>();
        int checked = 0;
        for (JavaClass c : classes) {
            // Public classes only: a private nested class (a record, say) is not JADE's API.
            if (!c.getPackageName().startsWith("jade") || c.isInterface() || !c.getModifiers().contains(JavaModifier.PUBLIC)) {
                continue;
            }
            for (JavaMethod m : c.getMethods()) {
                if (!userVisible(m)) {
                    continue;
                }
                checked++;
                String name = c.getName() + "." + m.getName();
                if (reachesNothing(m) && !DOCUMENTED_NO_OPS.containsKey(name)) {
                    silent.add(m.getFullName());
                }
            }
        }
        assertEquals(true, checked > 300, "checked only " + checked + " methods: the import found too few jade.* classes");
        assertEquals(Set.of(), silent, "JADE-named methods with a body that reaches nothing (fill them in, or throw, or list them "
                + "above with JADE's documentation as the reason)");
    }

    @Test
    void everyListedNoOpExistsAndIsStillEmpty() {
        Set<String> stale = new TreeSet<>(DOCUMENTED_NO_OPS.keySet());
        for (JavaClass c : classes) {
            for (JavaMethod m : c.getMethods()) {
                String name = c.getName() + "." + m.getName();
                if (DOCUMENTED_NO_OPS.containsKey(name) && reachesNothing(m)) {
                    stale.remove(name);
                }
            }
        }
        assertEquals(Set.of(), stale, "listed as documented no-ops but missing or no longer empty: take them off the list");
    }
}
