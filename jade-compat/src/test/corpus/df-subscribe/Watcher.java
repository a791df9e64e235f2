import jade.core.AID;
import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.proto.SubscriptionInitiator;
import jade.util.leap.Iterator;

/**
 * Subscribes to the DF for the weather services, as JADE's DF subscription examples do: it is told
 * at once of the one registered before, then of a registration made later, then of its deregistration
 * (a description without services). Each step is asked for only after the previous notification, so
 * the lines come in one order on any schedule.
 */
public class Watcher extends Agent {
    private int notifications;

    @Override
    protected void setup() {
        // One registration before the subscription: "early", created here, registers when asked.
        try {
            getContainerController().createNewAgent("early", "Member", null).start();
        } catch (Exception e) {
            System.out.println("could not create early: " + e);
        }
        ask("early", "register weather forecast");
        DFAgentDescription template = new DFAgentDescription();
        ServiceDescription sd = new ServiceDescription();
        sd.setType("weather");
        template.addServices(sd);
        ACLMessage subscribe = DFService.createSubscriptionMessage(this, getDefaultDF(), template, null);
        System.out.println("subscription: " + ACLMessage.getPerformative(subscribe.getPerformative()) + " to "
                + ((AID) subscribe.getAllReceiver().next()).getLocalName() + " protocol " + subscribe.getProtocol());
        addBehaviour(new SubscriptionInitiator(this, subscribe) {
            @Override
            protected void handleInform(ACLMessage inform) {
                notifications++;
                try {
                    DFAgentDescription[] found = DFService.decodeNotification(inform.getContent());
                    for (DFAgentDescription d : found) {
                        StringBuilder b = new StringBuilder("notification " + notifications + " from "
                                + inform.getSender().getLocalName() + ": " + d.getName().getLocalName());
                        Iterator it = d.getAllServices();
                        if (!it.hasNext()) {
                            b.append(" (no services: deregistered)");
                        }
                        while (it.hasNext()) {
                            ServiceDescription s = (ServiceDescription) it.next();
                            b.append(" ").append(s.getType()).append("/").append(s.getName());
                        }
                        System.out.println(b);
                    }
                } catch (FIPAException fe) {
                    System.out.println("could not decode: " + fe.getMessage());
                }
                if (notifications == 1) {
                    ask("late", "register weather radar");
                } else if (notifications == 2) {
                    ask("late", "deregister");
                } else {
                    cancel(getDefaultDF(), true);
                    myAgent.doDelete();
                }
            }
        });
    }

    /** Asks a member to do something and waits until it says it has. */
    private void ask(String who, String what) {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.addReceiver(new AID(who, AID.ISLOCALNAME));
        m.setContent(what);
        m.setConversationId("ask-" + who + "-" + what.replace(' ', '-'));
        send(m);
        ACLMessage r = blockingReceive(MessageTemplate.MatchConversationId(m.getConversationId()));
        System.out.println(who + " " + r.getContent());
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
