import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.SequentialBehaviour;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.proto.AchieveREInitiator;
import jade.proto.ContractNetInitiator;
import jade.proto.SimpleAchieveREInitiator;

import java.util.Vector;

/**
 * Asks the server for squares (SimpleAchieveREInitiator), a cube, another cube whose INFORM and
 * results registered steps handle, and runs three contract nets, one after the other.
 */
public class Client extends Agent {
    private ACLMessage request(String ontology, String content) {
        ACLMessage m = new ACLMessage(ACLMessage.REQUEST);
        m.addReceiver(new AID("server", AID.ISLOCALNAME));
        m.setProtocol(FIPANames.InteractionProtocol.FIPA_REQUEST);
        m.setOntology(ontology);
        m.setContent(content);
        return m;
    }

    private SimpleAchieveREInitiator square(String n) {
        return new SimpleAchieveREInitiator(this, request("square", n)) {
            @Override
            protected ACLMessage prepareRequest(ACLMessage msg) {
                System.out.println("client: asking the square of " + msg.getContent());
                return msg;
            }

            @Override
            protected void handleAgree(ACLMessage agree) {
                System.out.println("client: agreed");
            }

            @Override
            protected void handleRefuse(ACLMessage refuse) {
                System.out.println("client: refused");
            }

            @Override
            protected void handleInform(ACLMessage inform) {
                System.out.println("client: square " + inform.getContent());
            }

            @Override
            protected void handleAllResultNotifications(Vector notifications) {
                System.out.println("client: " + notifications.size() + " result(s)");
            }
        };
    }

    private ContractNetInitiator buy(String what, boolean accept) {
        ACLMessage cfp = new ACLMessage(ACLMessage.CFP);
        cfp.addReceiver(new AID("server", AID.ISLOCALNAME));
        cfp.setProtocol(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET);
        cfp.setConversationId("buy-" + what);
        cfp.setContent(what);
        return new ContractNetInitiator(this, cfp) {
            @Override
            protected void handleAllResponses(Vector responses, Vector acceptances) {
                for (Object o : responses) {
                    ACLMessage r = (ACLMessage) o;
                    System.out.println("client: " + ACLMessage.getPerformative(r.getPerformative()) + " " + r.getContent());
                    if (r.getPerformative() == ACLMessage.PROPOSE) {
                        ACLMessage a = r.createReply();
                        a.setPerformative(accept ? ACLMessage.ACCEPT_PROPOSAL : ACLMessage.REJECT_PROPOSAL);
                        acceptances.add(a);
                    }
                }
            }

            @Override
            protected void handleInform(ACLMessage inform) {
                System.out.println("client: " + inform.getContent());
            }
        };
    }

    @Override
    protected void setup() {
        SequentialBehaviour s = new SequentialBehaviour(this) {
            @Override
            public int onEnd() {
                myAgent.doDelete();
                return 0;
            }
        };
        s.addSubBehaviour(square("7"));
        s.addSubBehaviour(square("-1"));
        s.addSubBehaviour(new AchieveREInitiator(this, request("cube", "3")) {
            @Override
            protected void handleInform(ACLMessage inform) {
                System.out.println("client: cube " + inform.getContent());
            }
        });
        AchieveREInitiator registered = new AchieveREInitiator(this, request("cube", "2"));
        registered.registerHandleInform(new jade.core.behaviours.OneShotBehaviour(this) {
            @Override
            public void action() {
                ACLMessage inform = (ACLMessage) getDataStore().get(registered.REPLY_KEY);
                System.out.println("client: the registered step read cube " + inform.getContent());
            }
        });
        registered.registerHandleAllResultNotifications(new jade.core.behaviours.OneShotBehaviour(this) {
            @Override
            public void action() {
                Vector v = (Vector) getDataStore().get(registered.ALL_RESULT_NOTIFICATIONS_KEY);
                System.out.println("client: the registered step saw " + v.size() + " result(s)");
            }
        });
        s.addSubBehaviour(registered);
        s.addSubBehaviour(buy("tea", true));
        ACLMessage coffee = new ACLMessage(ACLMessage.CFP);
        coffee.addReceiver(new AID("server", AID.ISLOCALNAME));
        coffee.setProtocol(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET);
        coffee.setConversationId("buy-coffee");
        coffee.setContent("coffee");
        ContractNetInitiator registeredNet = new ContractNetInitiator(this, coffee);
        registeredNet.registerHandleAllResponses(new jade.core.behaviours.OneShotBehaviour(this) {
            @Override
            public void action() {
                Vector responses = (Vector) getDataStore().get(registeredNet.ALL_RESPONSES_KEY);
                Vector acceptances = (Vector) getDataStore().get(registeredNet.ALL_ACCEPTANCES_KEY);
                ACLMessage offer = (ACLMessage) responses.get(0);
                System.out.println("client: the registered step accepts " + offer.getContent());
                ACLMessage accept = offer.createReply();
                accept.setPerformative(ACLMessage.ACCEPT_PROPOSAL);
                acceptances.add(accept);
            }
        });
        registeredNet.registerHandleInform(new jade.core.behaviours.OneShotBehaviour(this) {
            @Override
            public void action() {
                System.out.println("client: the registered step read " + ((ACLMessage) getDataStore().get(registeredNet.REPLY_KEY)).getContent());
            }
        });
        s.addSubBehaviour(registeredNet);
        s.addSubBehaviour(buy("salt", false));
        s.addSubBehaviour(new jade.core.behaviours.WakerBehaviour(this, 300) {
            // lets the server print its rejection before the next CFP
        });
        s.addSubBehaviour(buy("gold", true));
        s.addSubBehaviour(new jade.core.behaviours.OneShotBehaviour(this) {
            @Override
            public void action() {
                ACLMessage cfp = new ACLMessage(ACLMessage.CFP);
                cfp.addReceiver(new AID("server", AID.ISLOCALNAME));
                cfp.setProtocol(FIPANames.InteractionProtocol.FIPA_ITERATED_CONTRACT_NET);
                cfp.setConversationId("haggle");
                cfp.setContent("bread");
                myAgent.send(cfp);
                jade.lang.acl.MessageTemplate mine = jade.lang.acl.MessageTemplate.MatchConversationId("haggle");
                ACLMessage offer = myAgent.blockingReceive(mine);
                for (String again : new String[] {"bread, cheaper", "bread, cheaper still"}) {
                    System.out.println("client: offered " + ACLMessage.getPerformative(offer.getPerformative()) + " " + offer.getContent());
                    ACLMessage next = offer.createReply();
                    next.setPerformative(ACLMessage.CFP);
                    next.setContent(again);
                    myAgent.send(next);
                    offer = myAgent.blockingReceive(mine);
                }
                System.out.println("client: offered " + ACLMessage.getPerformative(offer.getPerformative()) + " " + offer.getContent());
                ACLMessage accept = offer.createReply();
                accept.setPerformative(ACLMessage.ACCEPT_PROPOSAL);
                myAgent.send(accept);
                System.out.println("client: " + myAgent.blockingReceive(mine).getContent());
            }
        });
        addBehaviour(s);
    }

    @Override
    protected void takeDown() {
        System.exit(0);
    }
}
